// An in-place update that reads neighbours (Gauss-Seidel): iteration i reads
// u[i - 1], which iteration i - 1 already updated. Rejected, with the rewrite.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void gauss_seidel(DPGEN_INOUT double* u, DPGEN_IN const double* f, int n) {
  for (int i = 1; i < n - 1; ++i)
    u[i] = 0.5 * (u[i - 1] + u[i + 1]) - f[i];
  // CHECK: inplace_stencil.cpp:[[@LINE-1]]:19: error: in-place array 'u' is read here at an element another iteration or loop may already have updated
  // CHECK-SAME: write the new values to a separate DPGEN_OUT array
  // Every read that breaks the rule is reported (u[i + 1] too), in one run:
  // CHECK: inplace_stencil.cpp:[[@LINE-4]]:30: error: in-place array 'u' is read here
  // CHECK: 2 errors generated.
}
