// A kernel calling itself.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i];
  k(a, out, n - 1);
  // CHECK: recursion.cpp:[[@LINE-1]]:3: error: recursive call to 'k' is outside the kernel subset
}
