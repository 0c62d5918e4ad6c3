// --print-after=derive: the partial of each store w.r.t. each read of an
// input, one read at a time, from the rules of the operation table (ops.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=derive %s --out-dir %t -- -I%runtime_inc | FileCheck %s
#include "dpgen/annotate.hpp"

#include <algorithm>
#include <cmath>

// Per argument of a two-argument function: neither partial is dropped.
// CHECK-LABEL: partials of polar
// CHECK-NEXT: d r[i] / d x[i] = x[i] / hypot_v0
// CHECK-NEXT: where hypot_v0 = std::hypot(x[i], y[i])
// CHECK-NEXT: d t[i] / d x[i] = -(y[i] / (x[i] * x[i] + y[i] * y[i]))
// CHECK-NEXT: d r[i] / d y[i] = y[i] / hypot_v0
// CHECK-NEXT: where hypot_v0 = std::hypot(x[i], y[i])
// CHECK-NEXT: d t[i] / d y[i] = x[i] / (x[i] * x[i] + y[i] * y[i])
DPGEN_KERNEL void polar(DPGEN_IN const double* x, DPGEN_IN const double* y, DPGEN_OUT double* r,
                        DPGEN_OUT double* t, int n) {
  for (int i = 0; i < n; ++i) {
    r[i] = std::hypot(x[i], y[i]);
    t[i] = std::atan2(y[i], x[i]);
  }
}

// min/max pick an argument; a read in a branch the store does not take has an
// exact zero where the branch's condition fails; floor has no derivative.
// CHECK-LABEL: partials of limit
// CHECK-NEXT: d out[i] / d a[i] = a[i] <= c ? 1.0 : 0.0
// CHECK-NEXT: d out[i] / d a[i] = 0 (exact)
DPGEN_KERNEL void limit(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double c) {
  for (int i = 0; i < n; ++i)
    out[i] = std::min(a[i], c) + std::floor(a[i]);
}
