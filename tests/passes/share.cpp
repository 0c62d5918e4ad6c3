// --print-after=share: the values an interior strip of an adjoint computes
// once per iteration because its cells' terms read them at several shifts of
// the innermost counter (share.hpp), and what is not shared; emit prints the
// strips and the buffers.
// RUN: rm -rf %t && mkdir -p %t
// RUN: %dpgen --print-after=share %s --out-dir %t -- -I%runtime_inc | FileCheck %s
// RUN: FileCheck %s --check-prefix=CODE < %t/share_adjoint.cpp
// RUN: %dpgen --no-share %s --out-dir %t/off -- -I%runtime_inc
// RUN: FileCheck %s --check-prefix=OFF < %t/off/share_adjoint.cpp
// RUN: %dpgen --print-after=share %S/../styles/shifted_quotients.cpp --out-dir %t/styles -- -I%runtime_inc | FileCheck %s --check-prefix=STYLE
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
// With --no-share each cell computes it, as before the pass.
// OFF-LABEL: void speed_switch_adjoint(
// OFF-NOT: shared0
// OFF: const double c = u[i] / dx;
// OFF-NOT: shared0
// OFF-LABEL: void speed_switch_adjoint_checked(

// A term under run-time guards (the upwind switch as an if/else) shares what
// the source computed before branching: the guards' locals (c). Not a local
// only the guarded branch computes (s, the sqrt).
// CHECK-LABEL: shared in branch_switch
// CHECK-NEXT: cells of [q, u]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: cells of [q]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void branch_switch(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                DPGEN_OUT double* out, int n, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double c = u[i] / dx;
    if (c > 0.0) {
      const double s = std::sqrt(1.0 + std::fabs(q[i]));
      out[i] = c * s * (q[i] - q[i - 1]);
    } else
      out[i] = c * (q[i + 1] - q[i]);
  }
}
// CODE-LABEL: void branch_switch_adjoint(
// CODE: auto interior = [=](const std::ptrdiff_t strip_lo, const std::ptrdiff_t strip_hi) {
// CODE: // out[i] reads q[i - 1] at i = c_i + 1: acc += ∂out[i]/∂q[i - 1] · out_adj[i]
// CODE-NEXT: {
// CODE-NEXT: const std::ptrdiff_t i = c_i + 1;
// CODE-NEXT: const double c = shared0[i - shared0_lo];
// CODE-NEXT: if (c > 0.0) {
// CODE-NEXT: const double s = std::sqrt(1.0 + std::abs(q[i]));

// Two guards (nested ifs): a value in the first guard is shared (it runs
// unconditionally), one in the second is not (it runs after &&, where the
// first holds).
// CHECK-LABEL: shared in nested_guards
// CHECK-NEXT: cells of [q]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void nested_guards(DPGEN_IN const double* q, const double* u, const double* m,
                                DPGEN_OUT double* out, int n, double dx) {
  for (int i = 1; i < n - 1; ++i)
    if (u[i] / dx > 0.5)
      if (std::sqrt(std::fabs(m[i])) > 0.1)
        out[i] = q[i + 1] - q[i - 1];
}
// CODE-LABEL: void nested_guards_adjoint(
// CODE: auto interior = [=](const std::ptrdiff_t strip_lo, const std::ptrdiff_t strip_hi) {
// CODE: if (shared0[i - shared0_lo] > 0.5 && std::sqrt(std::abs(m[i])) > 0.1) {

// Values whose reads differ by a shift of the counter are one value: the
// quotient at i + 1 is the one at i one iteration later (one buffer; a term
// reads it one element on). Not where the counter occurs outside an index
// (1.0 + i, 2.0 + i): their texts would differ, and they stay two buffers.
// CHECK-LABEL: shared in moved_reads
// CHECK-NEXT: cells of [q]: shared0 = q[i] / (1.0 + std::abs(q[i])) at i = c_i - 1 ..= c_i + 2
// CHECK-NEXT: cells of [q]: shared1 = u[i] / (1.0 + static_cast<double>(i)) at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: cells of [q]: shared2 = u[i + 1] / (2.0 + static_cast<double>(i)) at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void moved_reads(DPGEN_IN const double* q, const double* u, DPGEN_OUT double* out,
                              int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double a = q[i] / (1.0 + std::fabs(q[i]));
    const double b = q[i + 1] / (1.0 + std::fabs(q[i + 1]));
    const double d = q[i + 1] - q[i - 1];
    out[i] = (a + b) * d + (u[i] / (1.0 + i) + u[i + 1] / (2.0 + i)) * d;
  }
}
// CODE-LABEL: void moved_reads_adjoint(
// CODE: auto interior = [=](const std::ptrdiff_t strip_lo, const std::ptrdiff_t strip_hi) {
// CODE: const double b = shared0[i + 1 - shared0_lo];

// A product inside a value is shared where no sum inside the value takes it
// (through negations): GCC contracts a product into a multiply-add only where
// every use of it is a sum, so exp(-(u * u)) computes the same in the buffer
// as in place. Not sqrt(u * u + 1.0) or 1.0 / (1.0 - u * u * 0.5), whose
// products a sum takes, nor 1.0 / (1.0 + (u + u)) (GCC writes u + u as
// u * 2.0), nor a division by 4.0 (a product by 0.25).
// CHECK-LABEL: shared in products
// CHECK-NEXT: cells of [q]: shared0 = std::exp(-(u[i] * u[i])) at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void products(DPGEN_IN const double* q, const double* u, const double* v,
                           DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = (std::exp(-(u[i] * u[i])) + std::sqrt(v[i] * v[i] + 1.0) +
              1.0 / (1.0 - v[i] * v[i] * 0.5) + 1.0 / (1.0 + (v[i] + v[i])) + v[i] / 4.0) *
             (q[i + 1] - q[i - 1]);
}

// A division GCC writes as a product is not a shared value: by -2.0 (x * -0.5),
// by a constant local (h = 4.0: x * 0.25), by an integer 2 (x * 0.5).
// CHECK-LABEL: shared in hidden_products
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void hidden_products(DPGEN_IN const double* q, const double* u, DPGEN_OUT double* out,
                                  int n) {
  const double h = 4.0;
  for (int i = 1; i < n - 1; ++i)
    out[i] = (u[i] / -2.0 + u[i] / h + u[i] / 2) * (q[i + 1] - q[i - 1]);
}

// Nor a value whose product the term computes outside it too (here through a
// local, r2 = u * u): in place that product has a use other than the sum, so it
// is not contracted; with the value read from a buffer the sum would be its only
// use, and the compiler could contract it there (another rounding of sqrt).
// CHECK-LABEL: shared in product_outside
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void product_outside(DPGEN_IN const double* q, const double* u,
                                  DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double r2 = u[i] * u[i];
    out[i] = (std::exp(-r2) + std::sqrt(r2 + 1.0)) * (q[i + 1] - q[i - 1]);
  }
}

// Locals that nest (each used twice by the next): expanded into a tree, p32
// would have 2^32 nodes. The pass compares products through locals within a
// node budget, so this takes as long as any kernel (it hung before).
// CHECK-LABEL: shared in local_chain
// CHECK-NEXT: cells of [q]: shared0 = std::sqrt(1.0 + std::abs(u[i])) at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void local_chain(DPGEN_IN const double* q, const double* u, DPGEN_OUT double* out,
                              int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double p0 = u[i] * 0.5;
    const double p1 = p0 * p0 + p0;
    const double p2 = p1 * p1 + p1;
    const double p3 = p2 * p2 + p2;
    const double p4 = p3 * p3 + p3;
    const double p5 = p4 * p4 + p4;
    const double p6 = p5 * p5 + p5;
    const double p7 = p6 * p6 + p6;
    const double p8 = p7 * p7 + p7;
    const double p9 = p8 * p8 + p8;
    const double p10 = p9 * p9 + p9;
    const double p11 = p10 * p10 + p10;
    const double p12 = p11 * p11 + p11;
    const double p13 = p12 * p12 + p12;
    const double p14 = p13 * p13 + p13;
    const double p15 = p14 * p14 + p14;
    const double p16 = p15 * p15 + p15;
    const double p17 = p16 * p16 + p16;
    const double p18 = p17 * p17 + p17;
    const double p19 = p18 * p18 + p18;
    const double p20 = p19 * p19 + p19;
    const double p21 = p20 * p20 + p20;
    const double p22 = p21 * p21 + p21;
    const double p23 = p22 * p22 + p22;
    const double p24 = p23 * p23 + p23;
    const double p25 = p24 * p24 + p24;
    const double p26 = p25 * p25 + p25;
    const double p27 = p26 * p26 + p26;
    const double p28 = p27 * p27 + p27;
    const double p29 = p28 * p28 + p28;
    const double p30 = p29 * p29 + p29;
    const double p31 = p30 * p30 + p30;
    const double p32 = p31 * p31 + p31;
    out[i] = (std::sqrt(1.0 + std::fabs(u[i])) + p32) * (q[i + 1] - q[i - 1]);
  }
}

// Not shared: a quotient only in a conditional's arm (the source
// computes it where the condition holds: q's partials at i = c_i - 1 and
// c_i + 1 are 1.0 / (1.0 + |u[i]|) in that arm), one under the store's
// run-time guard, one read at one shift only (exp(u[i])), one with an integer
// division inside (it may trap where the source would not run it), a pow
// (not a costly call: GCC writes pow(x, 2.0) as a product). Shared: w, whose
// product only the division takes.
// CHECK-LABEL: shared in not_shared
// CHECK-NEXT: cells of [q, u]: shared0 = u[i] * dt / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: cells of [q]: shared0 = u[i] * dt / dx at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void not_shared(DPGEN_IN const double* q, DPGEN_IN const double* u,
                             DPGEN_IN const double* mask, DPGEN_OUT double* a,
                             DPGEN_OUT double* b, DPGEN_OUT double* c, DPGEN_OUT double* d,
                             DPGEN_OUT double* e, int n, double dt, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double w = u[i] * dt / dx;
    a[i] = w * (q[i + 1] - q[i - 1]) +
           (q[i] > 0.0 ? (q[i + 1] - q[i - 1]) / (1.0 + std::fabs(u[i])) : 0.0);
    if (mask[i] > 0.0)
      b[i] = std::sqrt(2.0 + std::fabs(q[i])) * (q[i + 1] - q[i - 1]);
    c[i] = std::exp(u[i]) * q[i];
    d[i] = std::sqrt(1.0 + std::fabs(u[i] / static_cast<double>(n / 2))) * (q[i + 1] - q[i - 1]);
    e[i] = std::pow(u[i], 2.0) * (q[i + 1] - q[i - 1]);
  }
}

// Not shared either: shifts 18 apart (more than 16), a read at an index that
// is not affine in the counter (through a map).
// CHECK-LABEL: shared in far_apart
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void far_apart(DPGEN_IN const double* q, const double* u, DPGEN_OUT double* out,
                            int n) {
  for (int i = 9; i < n - 9; ++i)
    out[i] = std::sqrt(1.0 + std::fabs(u[i])) * (q[i + 9] - q[i - 9]);
}
// One value at shifts far apart gets a buffer for each run of shifts at most
// 16 apart: the quotient at c_i - 1 and c_i + 1, and (spelled at i + 20) at
// c_i + 19 and c_i + 21.
// CHECK-LABEL: shared in two_runs
// CHECK-NEXT: cells of [q]: shared0 = u[i] / (1.0 + std::abs(u[i])) at i = c_i - 1 ..= c_i + 1
// CHECK-NEXT: cells of [q]: shared1 = u[i] / (1.0 + std::abs(u[i])) at i = c_i + 19 ..= c_i + 21
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void two_runs(DPGEN_IN const double* q, const double* u, DPGEN_OUT double* out,
                           int n) {
  for (int i = 1; i < n - 21; ++i)
    out[i] = (u[i] / (1.0 + std::fabs(u[i])) + u[i + 20] / (1.0 + std::fabs(u[i + 20]))) *
             (q[i + 1] - q[i - 1]);
}
// CODE-LABEL: void two_runs_adjoint(
// CODE: auto interior = [=](const std::ptrdiff_t strip_lo, const std::ptrdiff_t strip_hi) {
// CODE: shared0[i - shared0_lo] + shared1[i + 20 - shared1_lo]

// CHECK-LABEL: shared in through_map
// CHECK-NEXT: // -- IR after share
DPGEN_KERNEL void through_map(DPGEN_IN const double* q, const double* coef, const int* map,
                              DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = std::sqrt(1.0 + std::fabs(coef[map[i]])) * (q[i + 1] - q[i - 1]);
}

// At most 16 buffers per loop (each up to 272 values on the stack of the
// thread that runs the strip), in order of first use: the 17th quotient is
// computed in place.
// CHECK-LABEL: shared in seventeen
// CHECK: shared15 = u[i] / (16.0 + a)
// CHECK-NOT: shared16
// CHECK: // -- IR after share
DPGEN_KERNEL void seventeen(DPGEN_IN const double* q, DPGEN_IN const double* u,
                            DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    const double a = std::fabs(u[i]);
    const double s = u[i] / (1.0 + a) + u[i] / (2.0 + a) + u[i] / (3.0 + a) + u[i] / (4.0 + a) +
                     u[i] / (5.0 + a) + u[i] / (6.0 + a) + u[i] / (7.0 + a) + u[i] / (8.0 + a) +
                     u[i] / (9.0 + a) + u[i] / (10.0 + a) + u[i] / (11.0 + a) +
                     u[i] / (12.0 + a) + u[i] / (13.0 + a) + u[i] / (14.0 + a) +
                     u[i] / (15.0 + a) + u[i] / (16.0 + a) + u[i] / (17.0 + a);
    out[i] = s * (q[i + 1] - q[i - 1]);
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
// CODE: shared0_[i - shared0_lo] = std::sqrt(1.0 + std::abs(dpgen_buf_w[i]));

// The style kernels (tests/styles/shifted_quotients.cpp): the conductivity
// at c, c + 1 and c - 1 is one buffer; the 9-point kernel shares its weight
// along each of the three rows a cell's terms read it in; the flux form's
// cm, c0, cp are one buffer, read in its guarded terms too (the upwind
// switch); the weight read at n - 2 - i is the one at n - 1 - i an
// iteration later; the Gaussian weights at q[i - 1], q[i], q[i + 1] are one
// buffer, read from q[c_i - 2] to q[c_i + 2].
// STYLE-LABEL: shared in sqrt_conductivity2d
// STYLE-NEXT: cells of [phi]: shared0 = std::sqrt(1.0f + std::abs(phi[c])) at i = c_i - 1 ..= c_i + 1, j = c_j
// STYLE-NEXT: where c = j * nx + i
// STYLE-NEXT: // -- IR after share
// STYLE-LABEL: shared in ninepoint_weights
// STYLE-NEXT: cells of [a]: shared0 = 1.0 / (2.0 + std::abs(a[j * nx + i])) at i = c_i - 1 ..= c_i + 1, j = c_j + 1
// STYLE-NEXT: cells of [a]: shared1 = 1.0 / (2.0 + std::abs(a[j * nx + i])) at i = c_i - 1 ..= c_i + 1, j = c_j
// STYLE-NEXT: cells of [a]: shared2 = 1.0 / (2.0 + std::abs(a[j * nx + i])) at i = c_i - 1 ..= c_i + 1, j = c_j - 1
// STYLE-NEXT: // -- IR after share
// STYLE-NEXT: shared in ratio_in_branch
// STYLE-NEXT: // -- IR after share
// STYLE-NEXT: shared in flux_form_upwind
// STYLE-NEXT: cells of [q, u]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// STYLE-NEXT: cells of [q]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// STYLE-NEXT: cells of [u]: shared0 = u[i] / dx at i = c_i - 1 ..= c_i + 1
// STYLE-NEXT: // -- IR after share
// STYLE-NEXT: shared in mirrored_weights
// STYLE-NEXT: cells of [q]: shared0 = 1.0 / (1.0 + std::abs(w[n - 1 - i])) at i = c_i ..= c_i + 1
// STYLE-NEXT: // -- IR after share
// STYLE-NEXT: shared in gaussian_neighbours
// STYLE-NEXT: cells of [q]: shared0 = std::exp(-(q[i - 1] * q[i - 1] * inv_two_s2)) at i = c_i - 1 ..= c_i + 3
// STYLE-EMPTY:
