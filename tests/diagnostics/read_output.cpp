// Reading an output inside the kernel.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n; ++i)
    out[i] = a[i] + out[i - 1];
  // CHECK: read_output.cpp:[[@LINE-1]]:21: error: reads output 'out': the adjoint has only the output's seed, not its values
}
