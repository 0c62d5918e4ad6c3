// A file without any DPGEN_KERNEL.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
// CHECK: no_kernel.cpp:1:1: error: no DPGEN_KERNEL function in this file
#include "dpgen/annotate.hpp"

void k(const double* a, double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i];
}
