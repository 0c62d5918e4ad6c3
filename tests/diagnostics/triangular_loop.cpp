// Inner bounds that move with an outer counter are accepted when they are
// affine in it with constant coefficients (tests/styles/triangular.cpp).
// What is not: a bound quadratic in the counter, and one whose coefficient
// is a size. (A strided loop whose start moves is accepted too:
// tests/styles/parity_loops.cpp.)
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void quadratic(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < j * j; ++i)
      out[j * n * n + i] = a[j * n * n + i];
  // CHECK: triangular_loop.cpp:[[@LINE-2]]:25: error: upper bound of loop 'i' depends on loop 'j'
}

DPGEN_KERNEL void size_coefficient(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m * j; ++i)
      out[j * n * m + i] = a[i];
  // CHECK: triangular_loop.cpp:[[@LINE-2]]:25: error: upper bound of loop 'i' depends on loop 'j'
}
