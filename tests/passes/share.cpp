// --print-after=share: the values an interior strip of an adjoint computes
// once per iteration because its cells' terms read them at several shifts of
// the innermost counter (share.hpp), and what is not shared; emit prints the
// strips and the buffers.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=share %s --out-dir %t -- -I%runtime_inc | FileCheck %s
// RUN: FileCheck %s --check-prefix=CODE < %t/share_adjoint.cpp
#include "dpgen/annotate.hpp"

#include <cmath>

// The upwind switch: q's adjoint at cell c_i reads c at i = c_i - 1, c_i,
// c_i + 1; the fused loop of q and u, and q's loop alone, share it. u's loop
// alone reads it at i = c_i only: nothing shared there.
// CHECK-LABEL: shared in speed_switch
// CHECK-NEXT: cells of [q, u]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: cells of [q]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void speed_switch(DPGEN_IN const double* q, DPGEN_IN const double* u,
                               DPGEN_OUT double* out, int n, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double c = u[i] / dx;
    out[i] = std::fmax(c, 0.0) * (q[i] - q[i - 1]) + std::fmin(c, 0.0) * (q[i + 1] - q[i]);
  }
}
// CODE-LABEL: void speed_switch_adjoint(
// CODE: auto interior = [=](const std::ptrdiff_t strip_lo, const std::ptrdiff_t strip_hi) {
// CODE-NEXT: // u[i] / dx at i = c_i - 1 ..= c_i + 1, which the cells' terms read: once per iteration of
// CODE-NEXT: // the strip
// CODE-NEXT: double shared0[258];
// CODE-NEXT: const std::ptrdiff_t shared0_lo = strip_lo - 1;
// CODE-NEXT: for (std::ptrdiff_t i = shared0_lo; i < strip_hi + 1; ++i) {
// CODE-NEXT: shared0[i - shared0_lo] = u[i] / dx;
// CODE-NEXT: }
// CODE-NEXT: for (std::ptrdiff_t c_i = strip_lo; c_i < strip_hi; ++c_i) {
// CODE: const std::ptrdiff_t i = c_i - 1;
// CODE-NEXT: const double c = shared0[i - shared0_lo];
// CODE: // the interior in strips of 256 cells, which share values (above)
// CODE-NEXT: if (parallel_ok) {
// CODE-NEXT: #pragma omp parallel for
// CODE-NEXT: for (std::ptrdiff_t c_i = in_lo_i; c_i < in_hi_i; c_i += 256)
// CODE-NEXT: interior(c_i, std::min<std::ptrdiff_t>(c_i + 256, in_hi_i));

// Not shared: a real product (`u[i] * dt / dx`: a multiply-add could be
// contracted otherwise), a quotient only in a conditional's arm (the source
// computes it where the condition holds), one under the store's run-time
// guard, one read at one shift only (exp(u[i])).
// CHECK-LABEL: shared in not_shared
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void not_shared(DPGEN_IN const double* q, DPGEN_IN const double* u,
                             DPGEN_IN const double* mask, DPGEN_OUT double* a,
                             DPGEN_OUT double* b, DPGEN_OUT double* c, int n, double dt,
                             double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double w = u[i] * dt / dx;
    a[i] = w * (q[i + 1] - q[i - 1]) + (q[i] > 0.0 ? q[i + 1] / dx : q[i - 1]);
    if (mask[i] > 0.0)
      b[i] = std::sqrt(2.0 + std::fabs(q[i])) * (q[i + 1] - q[i - 1]);
    c[i] = std::exp(u[i]) * q[i];
  }
}

// A cell that sums over a counter inside it (k): that loop may run no
// iteration, and its terms compute nothing; not shared.
// CHECK-LABEL: shared in window_sum
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void window_sum(DPGEN_IN const double* q, DPGEN_OUT double* out, int n, int m) {
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < m; ++k)
      out[i] += q[i + k] / (1.0 + std::fabs(q[i]));
}

// A staged adjoint (a work array) shares in its stages. The buffer's name is
// not one of the kernel's (a parameter is called shared0).
// CHECK-LABEL: shared in two_stage
// CHECK-NEXT: stage 2: cells of [dpgen_buf_w]: shared0_ = std::sqrt(1.0 + std::abs(dpgen_buf_w[i])) at i = c_i - 1 ..= c_i + 1
DPGEN_KERNEL void two_stage(DPGEN_IN const double* q, DPGEN_OUT double* out, int n,
                            double shared0) {
  double w[4096];
  for (int i = 0; i < n; ++i)
    w[i] = q[i] / (shared0 + std::fabs(q[i]));
  for (int i = 1; i < n - 1; ++i)
    out[i] = std::sqrt(1.0 + std::fabs(w[i])) * (w[i + 1] - w[i - 1]);
}
// CODE-LABEL: void two_stage_nest2_adjoint(
// CODE: double shared0_[258];
// CODE: shared0_[i - shared0__lo] = std::sqrt(1.0 + std::abs(dpgen_buf_w[i]));
