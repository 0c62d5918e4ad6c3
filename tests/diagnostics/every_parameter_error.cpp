// Every error of a file in one run, also when a parameter is rejected
// (issue 20, defect 6): an in-place array through `double***`, a nameless
// parameter, then errors in the body of the same kernel; the rejected
// parameters' uses are not reported again; a second kernel's errors too.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_INOUT double*** u, DPGEN_IN const double* a, DPGEN_OUT double* out,
                    int n, double) {
  // CHECK: every_parameter_error.cpp:[[@LINE-2]]:43: error: DPGEN_INOUT parameter 'u' must be a flat pointer
  // CHECK: every_parameter_error.cpp:[[@LINE-2]]:34: error: every kernel parameter needs a name
  for (int i = 1; i < n; ++i) {
    u[0][0][i] = a[i];
    out[i] = a[i] * a[i - 1];
    while (n > 0) {
    }
    // CHECK: every_parameter_error.cpp:[[@LINE-2]]:5: error: a while loop is in the kernel subset as the for loop it is
  }
  goto done;
  // CHECK: every_parameter_error.cpp:[[@LINE-1]]:3: error: 'goto' is outside the kernel subset
done:
  return;
}
// CHECK-NOT: error: {{.*}}'u'

double undefined_helper(double);

DPGEN_KERNEL void k2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i] * undefined_helper(a[i]);
  // CHECK: every_parameter_error.cpp:[[@LINE-1]]:21: error: call to 'undefined_helper', whose body dpgen cannot see
}
