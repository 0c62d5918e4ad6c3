// An inner bound that depends on the outer counter.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < j; ++i)
      out[j * n + i] = a[j * n + i];
  // CHECK: triangular_loop.cpp:[[@LINE-2]]:25: error: upper bound of loop 'i' depends on loop 'j'
}
