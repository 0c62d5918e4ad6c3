// Two stores to one output at different indices in the same loop.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i < 4)
      out[i] = a[i];
    else
      out[i + 1] = a[i];
    // CHECK: two_write_indices.cpp:[[@LINE-1]]:7: error: output 'out' is written at 'out[i + 1]' here and at 'out[i]' on line 10 of the same loop
  }
}
