// Stores at `(j << lg) | i` (tests/styles/pow2_bits.cpp) that stay errors:
// dpgen reads the `|` as a sum only where the loops keep the low part below
// the power of two (here i reaches n, whose bit is the row's), and a shift
// by lg only where a kernel-level local holds 1 << lg.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %not %dpgen %s --out-dir %t -- -I%runtime_inc 2>&1 | FileCheck %s
// RUN: ls %t | %count 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void low_part_too_wide(DPGEN_IN const double* a, DPGEN_OUT double* b, int lg) {
  const int n = 1 << lg;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n + 1; ++i)
      b[(j << lg) | i] = a[j * (n + 1) + i];
  // CHECK: pow2_bits.cpp:[[@LINE-1]]:7: error: index of output 'b' must be an affine function of the loop counters (no conditional or data-dependent writes); `(j << lg) | i` is read as j * n + i only with a kernel-level `const int n = 1 << lg;` and loops that keep i in [0, n) [dpgen-output-index]
}

DPGEN_KERNEL void no_power_local(DPGEN_IN const double* a, DPGEN_OUT double* b, int lg, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      b[(j << lg) | i] = a[j * n + i];
  // CHECK: pow2_bits.cpp:[[@LINE-1]]:7: error: index of output 'b' must be an affine function of the loop counters (no conditional or data-dependent writes); `(j << lg) | i` is read as j * n + i only with a kernel-level `const int n = 1 << lg;` and loops that keep i in [0, n) [dpgen-output-index]
}
