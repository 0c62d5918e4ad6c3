// Two stores of one iteration that meet at i = 0 (out[i] and out[2 * i]):
// the second overwrites the first there. (Storing the same element twice, as
// in `out[i] = a; if (c) out[i] = b;`, is fine: the last store wins.)
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    if (a[i] > 0.0)
      out[2 * i] = 2.0 * a[i];
    // CHECK: written_twice.cpp:[[@LINE-1]]:7: error: output 'out' may be written twice in one iteration (first at line 11)
  }
}

// Paths that overlap (both hold where i > 4): the truth table over the
// conditions that decides disjoint paths (session 21) finds the row.
DPGEN_KERNEL void overlapping_arms(DPGEN_IN const double* a, DPGEN_OUT double* v, int n, int k) {
  for (int i = 0; i < n; ++i) {
    if (i > k || i > 4)
      v[i] = a[i];
    if (i > 4) {
      if (k < 2) {
        v[i] = 2.0 * a[i];
        // CHECK: written_twice.cpp:[[@LINE-1]]:9: error: output 'v' may be written twice
        // CHECK-SAME: in one iteration (first at line [[@LINE-5]])
      }
    }
  }
}

// An escape nested in an arm: the store after the if runs where the arm's
// store does not, also for the kernel below (no error at its lines).
// CHECK-NOT: written_twice.cpp:{{[0-9]+}}:{{[0-9]+}}: error
DPGEN_KERNEL void nested_escape_ok(DPGEN_IN const double* a, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i) {
    if (i > 2) {
      if (i > 4) {
        v[i] = a[i];
        continue;
      }
    }
    v[i] = 2.0 * a[i];
  }
}
