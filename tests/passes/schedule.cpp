// --print-after=schedule: where each read's adjoint is summed. Reads at
// affine indices form gather groups (one block per shift: iteration = cell -
// shift, over the store's domain); a read at a data-dependent index gets a
// scatter unit.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=schedule %s --out-dir %t -- -I%runtime_inc 2>/dev/null | FileCheck %s
#include "dpgen/annotate.hpp"

// CHECK-LABEL: schedule of stencil3
// CHECK-NEXT: gather a layout [1*i] base 0
// CHECK-NEXT: block bulk iteration [i = c_i + 1]
// CHECK-NEXT: domain {i: [1, n - 1)}
// CHECK-NEXT: term store #0 reads {a[i - 1]}: 0.25
// CHECK-NEXT: block bulk iteration = cell
// CHECK-NEXT: domain {i: [1, n - 1)}
// CHECK-NEXT: term store #0 reads {a[i]}: 0.5
// CHECK-NEXT: block bulk iteration [i = c_i - 1]
// CHECK-NEXT: domain {i: [1, n - 1)}
// CHECK-NEXT: term store #0 reads {a[i + 1]}: 0.25
DPGEN_KERNEL void stencil3(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 1; i < n - 1; ++i)
    b[i] = 0.25 * a[i - 1] + 0.5 * a[i] + 0.25 * a[i + 1];
}

// Rows: the shift is per counter of the layout.
// CHECK-LABEL: schedule of rows
// CHECK-NEXT: gather p layout [nx*j, 1*i] base 0
// CHECK-NEXT: block bulk iteration [j = c_j - 1]
// CHECK-NEXT: domain {i: [0, nx); j: [0, ny - 1)}
// CHECK-NEXT: term store #0 reads {p[(j + 1) * nx + i]}: 1.0
// CHECK-NEXT: block bulk iteration = cell
// CHECK-NEXT: domain {i: [0, nx); j: [0, ny - 1)}
// CHECK-NEXT: term store #0 reads {p[j * nx + i]}: -1.0
DPGEN_KERNEL void rows(DPGEN_IN const double* p, DPGEN_OUT double* d, int nx, int ny) {
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i)
      d[j * nx + i] = p[(j + 1) * nx + i] - p[j * nx + i];
}

// CHECK-LABEL: schedule of lookup
// CHECK-NEXT: scatter q from store #0
// CHECK-NEXT: q[idx[i]]: w
// CHECK-NEXT: remark at [[@LINE+4]]:18: read 'q[idx[i]]'
DPGEN_KERNEL void lookup(DPGEN_IN const double* q, const int* idx, DPGEN_OUT double* out, int n,
                         double w) {
  for (int i = 0; i < n; ++i)
    out[i] = w * q[idx[i]];
}
