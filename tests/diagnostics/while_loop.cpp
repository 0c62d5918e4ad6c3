// A while loop whose trip count depends on the data.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i = 0;
  while (a[i] > 0.0 && i < n) {
    // CHECK: while_loop.cpp:[[@LINE-1]]:3: error: while/do loops are outside the kernel subset
    out[i] = a[i];
    ++i;
  }
}
