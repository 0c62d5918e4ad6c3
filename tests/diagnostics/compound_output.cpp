// `*=` and `/=` on an output: accepted on an element the iteration has stored
// on the same path (tests/styles/compound_scale.cpp); refused where the
// element's value would be what the caller's array held (no store before it,
// a store under a condition the scaling is not under, or `+=` on it).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void scale_unstored(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    // CHECK-DAG: compound_output.cpp:[[@LINE+1]]:10: error: compound assignment '/=' to output 'b' needs the element's previous value, which the adjoint does not have; '=', '+=' and '-=' write outputs ('*=' and '/=' an element this iteration has stored) [dpgen-unsupported]
    b[i] /= a[i];
}

DPGEN_KERNEL void scale_conditional(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0.0)
      b[i] = a[i];
    // CHECK-DAG: compound_output.cpp:[[@LINE+1]]:10: error: compound assignment '*=' to output 'b' needs the element's previous value
    b[i] *= 2.0;
  }
}

DPGEN_KERNEL void scale_accumulated(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) {
    b[i] += a[i];
    // CHECK-DAG: compound_output.cpp:[[@LINE+1]]:5: error: reads output 'b' after '+=' (its previous contents)
    b[i] *= 2.0;
  }
}
