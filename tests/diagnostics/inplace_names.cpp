// Errors about an in-place array's stores name the array as the kernel does
// ('u'), not the buffer of new values dpgen makes for it ('u_new').
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s --implicit-check-not=u_new
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void row_sum_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* a, int n, int m) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      // CHECK: inplace_names.cpp:[[@LINE+1]]:7: error: in-place array 'u' is written at the same index by every iteration of loop 'j'
      u[i] += a[i * m + j] * u[i];
}

DPGEN_KERNEL void two_conditional_updates(DPGEN_INOUT double* u, DPGEN_IN const double* f, int n) {
  for (int i = 0; i < n; ++i) {
    if (u[i] > 0.5)
      u[i] = u[i] - 1.0 + 0.1 * f[i];
    if (u[i] < 0.0)
      // CHECK: inplace_names.cpp:[[@LINE+1]]:7: error: in-place array 'u' may be written twice in one iteration (first at line [[@LINE-2]])
      u[i] = u[i] * 3.0 * f[i];
  }
}
