// Writing to a differentiable input.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    a[i] = 0.0;
    // CHECK: write_input.cpp:[[@LINE-1]]:5: error: 'a' is written but is not a DPGEN_OUT parameter
  }
}
