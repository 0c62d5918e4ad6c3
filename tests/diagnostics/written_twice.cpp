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
