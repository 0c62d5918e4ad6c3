// Sums into an output spelled `x = x + e` (accepted forms:
// tests/styles/spelled_sums.cpp): refused where a term reads the output (its
// previous value, which the adjoint does not have) and where the target
// changes something as it is evaluated.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void chain_reads_neighbour(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n; ++i)
    // CHECK-DAG: spelled_sums.cpp:[[@LINE+1]]:14: error: reads output 'out': the adjoint has only the output's seed, not its values
    out[i] = out[i] + a[i] + out[i - 1];
}

DPGEN_KERNEL void counter_in_target(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int k = 0;
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: spelled_sums.cpp:[[@LINE+1]]:10: error: increment/decrement inside an expression is outside the kernel subset
    out[k++] = out[k++] + a[i];
}
