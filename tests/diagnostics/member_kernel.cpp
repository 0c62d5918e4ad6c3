// A kernel that is a member function.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

struct Solver {
  DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
    // CHECK: member_kernel.cpp:[[@LINE-1]]:21: error: a DPGEN_KERNEL must be a free function, not a member function
    for (int i = 0; i < n; ++i)
      out[i] = a[i];
  }
};
