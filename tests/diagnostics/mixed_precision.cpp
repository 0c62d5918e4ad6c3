// float input, double output.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const float* a, DPGEN_OUT double* out, int n) {
  // CHECK: mixed_precision.cpp:[[@LINE-1]]:19: error: kernel 'k' mixes float and double arrays ('out' is double)
  for (int i = 0; i < n; ++i)
    out[i] = a[i];
}
