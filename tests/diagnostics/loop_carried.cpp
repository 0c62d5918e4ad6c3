// A scalar carried from one iteration to the next (a prefix sum).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sum += a[i];
    // CHECK: loop_carried.cpp:[[@LINE-1]]:5: error: 'sum' is declared outside the loop and assigned inside it
    out[i] = sum;
  }
}
