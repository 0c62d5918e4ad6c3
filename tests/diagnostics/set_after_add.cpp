// An output added to ('+=') and then set ('=') in one iteration holds the
// value set (tests/styles/flux_sums.cpp: add_then_set); set under a
// condition, it holds either, which the adjoint cannot tell apart: refused.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void set_in_branch(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) {
    r[i] += a[i];
    if (a[i] > 0.0)
      // CHECK: set_after_add.cpp:[[@LINE+1]]:7: error: output 'r' is set here under a condition after '+=' added to it in this iteration: where the condition fails it keeps what it held before plus the sum, and where it holds it does not; set it before adding to it
      r[i] = 2.0 * a[i];
  }
}
