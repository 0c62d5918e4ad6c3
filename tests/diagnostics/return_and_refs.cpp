// Kernels returning a value and scalars by reference: what is outside the
// rules (accepted forms: tests/modern/kernels/return_*.cpp, scalarref_mass).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
// RUN: %not %dpgen --torch %S/../modern/kernels/return_checksum.cpp --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s --check-prefix=TORCH
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

// CHECK-DAG: return_and_refs.cpp:[[@LINE+1]]:{{[0-9]+}}: error: a DPGEN_KERNEL returns void, float or double, not 'int'; other results go to DPGEN_OUT arrays [dpgen-signature]
DPGEN_KERNEL int count(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i];
  return n;
}

DPGEN_KERNEL double first_positive(DPGEN_IN const double* a, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    s += a[i];
  if (n > 2)
    return s;
  // CHECK-DAG: return_and_refs.cpp:[[@LINE-1]]:5: error: a kernel that returns a value returns it once, as its last statement, not inside a branch (compute it in a local first) [dpgen-unsupported]
  return 0.0;
}

// CHECK-DAG: return_and_refs.cpp:[[@LINE+1]]:{{[0-9]+}}: error: DPGEN_OUT parameter 'm' is a const reference [dpgen-signature]
DPGEN_KERNEL void sum_into(DPGEN_IN const double* a, DPGEN_OUT const double& m, int n) {
  for (int i = 0; i < n; ++i)
    (void)a[i];
}

// CHECK-DAG: return_and_refs.cpp:[[@LINE+1]]:{{[0-9]+}}: error: unmarked parameter 'm' is a non-const reference: mark it DPGEN_OUT, or make it const [dpgen-signature]
DPGEN_KERNEL void unmarked(DPGEN_IN const double* a, DPGEN_OUT double* b, double& m, int n) {
  for (int i = 0; i < n; ++i)
    b[i] = a[i] * m;
}

// TORCH: return_checksum.cpp:{{[0-9]+}}:{{[0-9]+}}: error: kernel 'checksum': the return value is a scalar by reference, not a tensor; for --torch make it a one-element array (double* checksum_return) [dpgen-torch]
