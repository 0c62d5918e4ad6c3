// break leaves the iteration space data-dependent.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (a[i] < 0.0)
      break;
    // CHECK: break.cpp:[[@LINE-1]]:7: error: 'break' is outside the kernel subset
    out[i] = a[i];
  }
}
