// Write-once and buffer rules that depend on the sizes, checked on entry of
// the generated adjoint (not errors): component planes a stride parameter
// apart (tests/styles/component_planes.cpp), and the buffer of an output a
// sum's adjoint recomputes, whose row length the loops do not bound below
// (tests/styles/window_moments.cpp).
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen %s --out-dir %t -- -I%runtime_inc
// RUN: FileCheck %s --input-file %t/runtime_size_checks_adjoint.cpp
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void strided_planes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n,
                                 int stride) {
  for (int i = 0; i < n; ++i) {
    out[i] = u[i] * u[i];
    out[stride + i] = 2.0 * u[i];
  }
}
// CHECK: // Run-time check (not provable from the kernel alone): output 'out' is written by the stores on
// CHECK-NEXT: // lines 14 and 15 at elements [0, n - 1] and [stride, n + stride - 1], which must not overlap.
// CHECK: throw std::invalid_argument

DPGEN_KERNEL void signed_window(DPGEN_IN const double* a, DPGEN_OUT double* m, int nx, int ny,
                                int d) {
  for (int j = 0; j < ny; ++j)
    for (int i = d; i < nx - d; ++i) {
      double s = 0.0;
      for (int ii = i - d; ii <= i + d; ++ii)
        s += a[j * nx + ii];
      m[j * nx + i] = s * s;
    }
}
// CHECK: // Run-time check (not provable from the kernel alone): the elements of 'm' lie at increasing
// CHECK-NEXT: // indices along each loop (index coefficient 'nx' not negative), which the adjoint's buffer for
// CHECK-NEXT: // it assumes.
// CHECK-NEXT: if ((0) < (ny) && (d) < (-d + nx) && !((nx) >= 0)) {
