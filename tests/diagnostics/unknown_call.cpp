// A call to a function dpgen has no rule for.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

double helper(double x);

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = helper(a[i]);
  // CHECK: unknown_call.cpp:[[@LINE-1]]:14: error: call to 'helper', which dpgen cannot differentiate; the kernel subset calls only std::min
}
