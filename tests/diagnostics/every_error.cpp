// Every error of a file in one run: three statements of one kernel and a
// second kernel, each reported at its place; a poisoned declaration is not
// reported again where it is used; nothing is written.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

static double g = 1.0;
// CHECK: every_error.cpp:[[@LINE-1]]:15: error: global 'g' is static
double foo(double);

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double bad = g;
  // CHECK: every_error.cpp:[[@LINE-1]]:16: error: 'g' is global state
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * foo(a[i]);
    // CHECK: every_error.cpp:[[@LINE-1]]:21: error: call to 'foo', whose body dpgen cannot see
    out[i] = a[i] * bad;
    while (n > 0) {
    }
    // CHECK: every_error.cpp:[[@LINE-2]]:5: error: a while loop is in the kernel subset as the for loop it is
  }
}

DPGEN_KERNEL void k2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; i *= 2)
    // CHECK: every_error.cpp:[[@LINE-1]]:26: error: loop increment must be
    out[i] = a[i];
}
// CHECK-NOT: error:
