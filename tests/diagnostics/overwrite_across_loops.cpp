// A boundary element set after the loop that already wrote it: the forward
// overwrites, the adjoint would count it twice.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = 2.0 * a[i];
  out[0] = a[1];
  // CHECK: overwrite_across_loops.cpp:[[@LINE-1]]:3: error: output 'out' is also written on line 10 in another loop nest, and dpgen cannot prove the two write different elements
}
