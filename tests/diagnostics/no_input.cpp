// A kernel with nothing to differentiate.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(const double* a, DPGEN_OUT double* out, int n) {
  // CHECK: no_input.cpp:[[@LINE-1]]:19: error: kernel 'k' has no DPGEN_IN parameter: there is nothing to differentiate
  for (int i = 0; i < n; ++i)
    out[i] = a[i];
}
