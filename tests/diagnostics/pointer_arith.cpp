// Indexing through pointer arithmetic.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n - 1; ++i)
    out[i] = (a + 1)[i];
  // CHECK: pointer_arith.cpp:[[@LINE-1]]:15: error: pointer arithmetic is outside the kernel subset
}
