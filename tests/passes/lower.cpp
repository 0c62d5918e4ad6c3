// --print-after=lower: what the lowering hands on, on kernels written in the
// styles it rewrites (an accumulator, a triangular loop, an in/out array, a
// branch on the data, helper locals).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=lower %s --out-dir %t -- -I%runtime_inc | FileCheck %s
#include "dpgen/annotate.hpp"

#include <cmath>

// CHECK-LABEL: // -- IR after lower
// CHECK-NEXT: kernel smooth at [[@LINE+8]]:19
// CHECK-NEXT:   param in a : double
// CHECK-NEXT:   param out b : double
// CHECK-NEXT:   param scalar n : int
// CHECK-NEXT:   param scalar w : double
// CHECK-NEXT:   nest 0 key [0, -2]
// CHECK-NEXT:     for i : int in [1, n - 1)
// CHECK-NEXT:       store #0 b[i] = a[i] + w * (a[i - 1] - 2.0 * a[i] + a[i + 1])  at [[@LINE+3]]:5
DPGEN_KERNEL void smooth(DPGEN_IN const double* a, DPGEN_OUT double* b, int n, double w) {
  for (int i = 1; i < n - 1; ++i)
    b[i] = a[i] + w * (a[i - 1] - 2.0 * a[i] + a[i + 1]);
}

// A scalar accumulator becomes a hidden work array, written = init before the
// loop, += in it and read after it, each in a nest of its own; the triangular
// loop runs over its hull with the bound as the store's path condition.
// CHECK-LABEL: kernel prefix_norm
// CHECK: hidden dpgen_sum_s : double
// CHECK: nest 0 key [0, -2]
// CHECK-NEXT: for j : int in [0, n)
// CHECK-NEXT: store #0 dpgen_sum_s[j] = s
// CHECK-NEXT: where s = 0.0
// CHECK-NEXT: nest 1 key [0, 1, -3]
// CHECK-NEXT: for j : int in [0, n)
// CHECK-NEXT: for k : int in [0, n - 1 + 1)
// CHECK-NEXT: store #1 dpgen_sum_s[j] += a[k] * a[k]  if (k < j + 1)
// CHECK: store #2 out[j] = std::sqrt(dpgen_sum_s[j])
// CHECK: intermediate dpgen_sum_s
DPGEN_KERNEL void prefix_norm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int j = 0; j < n; ++j) {
    double s = 0.0;
    for (int k = 0; k <= j; ++k)
      s += a[k] * a[k];
    out[j] = std::sqrt(s);
  }
}

// An in/out array: the input and its output twin; a branch on the data is a
// path condition of the store.
// CHECK-LABEL: kernel relax
// CHECK-NEXT: param in u : double inout
// CHECK: param out u_new : double twin-of=u
// CHECK: store #0 u_new[i] = u[i] * r  if (u[i] > 0.0)
DPGEN_KERNEL void relax(DPGEN_INOUT double* u, int n, double r) {
  for (int i = 0; i < n; ++i)
    if (u[i] > 0.0)
      u[i] *= r;
}

// Integer bit logic in indices and conditions: i << 1 is the affine 2 * i;
// the colour test of a red-black sweep is a path condition.
// CHECK-LABEL: kernel bits
// CHECK: store #0 out[i] = 0.5 * (a[i << 1] + a[(i << 1) + 1])  if (((i + n) & 1) == 0)
// CHECK-NEXT: store #1 out[i] = a[i >> 1]  if !(((i + n) & 1) == 0)
DPGEN_KERNEL void bits(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (((i + n) & 1) == 0)
      out[i] = 0.5 * (a[i << 1] + a[(i << 1) + 1]);
    else
      out[i] = a[i >> 1];
}
