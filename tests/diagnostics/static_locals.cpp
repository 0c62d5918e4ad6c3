// Function-local statics: one that keeps a value from call to call (state the
// adjoint cannot see) or takes its value from the first call's inputs is
// refused; a constant table (`static const`, `static constexpr`, a constant
// initializer) is accepted (tests/styles/static_tables.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void counts_calls(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: static_locals.cpp:[[@LINE+1]]:17: error: static variable 'calls' is global state (it keeps its value from call to call), outside the kernel subset; a constant table is 'static const' or 'static constexpr' with a constant initializer [dpgen-unsupported]
  static double calls = 0.0;
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * calls;
}

DPGEN_KERNEL void first_call_scale(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  // CHECK-DAG: static_locals.cpp:[[@LINE+1]]:23: error: static variable 'scale' is global state
  static const double scale = a[0];
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * scale;
}
