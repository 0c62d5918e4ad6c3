// Writing global state.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

double total;

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    total = a[i];
    // CHECK: global_write.cpp:[[@LINE-1]]:5: error: write to 'total': global state is outside the kernel subset
  }
}
