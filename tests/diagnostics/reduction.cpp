// Every iteration writes the same output element: a reduction.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[0] = a[i];
  // CHECK: reduction.cpp:[[@LINE-1]]:5: error: output 'out' is written at the same index by every iteration of loop 'i'
}
