// Line buffers the way HPC codes write them (issue 20): local arrays larger
// than 64 elements (a macro, a constexpr, std::array), filled in one inner
// loop and read in a later one of the same outer iteration. Each buffer
// becomes a hidden work array with one row per iteration of the loops around
// its uses, which the adjoint recomputes. VLAs and C99 pointer casts, which
// are C: line_buffers_c.c.
#include "dpgen/annotate.hpp"

#include <array>
#include <cmath>

// NAS MG's resid, as written there (C89 counters, u1/u2 of a fixed size M
// larger than any line, a[] of constant coefficients): r = v - A u.
#define M 130
DPGEN_KERNEL void mg_resid(DPGEN_IN const double* u, DPGEN_IN const double* v,
                           DPGEN_OUT double* r, const double* a, int n1, int n2, int n3) {
  int i3, i2, i1;
  double u1[M], u2[M];
  for (i3 = 1; i3 < n3 - 1; i3++) {
    for (i2 = 1; i2 < n2 - 1; i2++) {
      for (i1 = 0; i1 < n1; i1++) {
        u1[i1] = u[(i3 * n2 + i2 - 1) * n1 + i1] + u[(i3 * n2 + i2 + 1) * n1 + i1] +
                 u[((i3 - 1) * n2 + i2) * n1 + i1] + u[((i3 + 1) * n2 + i2) * n1 + i1];
        u2[i1] = u[((i3 - 1) * n2 + i2 - 1) * n1 + i1] + u[((i3 - 1) * n2 + i2 + 1) * n1 + i1] +
                 u[((i3 + 1) * n2 + i2 - 1) * n1 + i1] + u[((i3 + 1) * n2 + i2 + 1) * n1 + i1];
      }
      for (i1 = 1; i1 < n1 - 1; i1++) {
        r[(i3 * n2 + i2) * n1 + i1] = v[(i3 * n2 + i2) * n1 + i1] -
                                     a[0] * u[(i3 * n2 + i2) * n1 + i1] -
                                     a[2] * (u2[i1] + u1[i1 - 1] + u1[i1 + 1]) -
                                     a[3] * (u2[i1 - 1] + u2[i1 + 1]);
      }
    }
  }
}

// The same residual of a nonlinear operator, buffers declared in the row
// loop with a constexpr length: r = v - A(u^3).
constexpr int kLine = 96;
DPGEN_KERNEL void mg_resid_cubic(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                 DPGEN_OUT double* r, int n1, int n2, int n3) {
  for (int i3 = 1; i3 < n3 - 1; i3++)
    for (int i2 = 1; i2 < n2 - 1; i2++) {
      double c1[kLine], c0[kLine];
      for (int i1 = 0; i1 < n1; i1++) {
        const double un = u[((i3 - 1) * n2 + i2) * n1 + i1], us = u[((i3 + 1) * n2 + i2) * n1 + i1];
        c1[i1] = un * un * un + us * us * us;
        const double uc = u[(i3 * n2 + i2) * n1 + i1];
        c0[i1] = uc * uc * uc;
      }
      for (int i1 = 1; i1 < n1 - 1; i1++)
        r[(i3 * n2 + i2) * n1 + i1] =
            v[(i3 * n2 + i2) * n1 + i1] - (4.0 * c0[i1] - c0[i1 - 1] - c0[i1 + 1] - c1[i1]);
    }
}

// A buffer filled in one loop and read at i - 1 and i + 1 in the next: a
// diffusion flux through a buffer of conductivities, length a constexpr.
constexpr int kMaxN = 512;
DPGEN_KERNEL void diffuse_buffered(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double kappa[kMaxN];
  for (int i = 0; i < n; ++i)
    kappa[i] = std::exp(-u[i] * u[i]);
  for (int i = 1; i < n - 1; ++i)
    out[i] = 0.5 * (kappa[i + 1] + kappa[i]) * (u[i + 1] - u[i]) -
             0.5 * (kappa[i] + kappa[i - 1]) * (u[i] - u[i - 1]);
}

// A std::array line buffer of 128 elements in a column sweep (the buffer
// read back at the same element in the filling loop, and at neighbours
// after it).
DPGEN_KERNEL void column_std_array(DPGEN_IN const double* a, DPGEN_OUT double* b,
                                   DPGEN_OUT double* c, int nx, int ny) {
  for (int i = 0; i < nx; ++i) {
    std::array<double, 128> col;
    for (int j = 0; j < ny; ++j) {
      col[j] = std::sin(a[j * nx + i]);
      b[j * nx + i] = col[j] * col[j];
    }
    for (int j = 1; j < ny - 1; ++j)
      c[j * nx + i] = col[j - 1] * col[j + 1];
  }
}

// Float, a buffer read only at shifted elements it fully covers (reads
// i + 2 of a fill over [2, n + 2)), counting down.
DPGEN_KERNEL void shifted_float(DPGEN_IN const float* x, DPGEN_OUT float* y, int n) {
  float t[200];
  for (int i = n + 1; i >= 2; --i)
    t[i] = x[i - 2] * x[i - 2];
  for (int i = 0; i < n; ++i)
    y[i] = t[i + 2] - 0.5f * x[i];
}

// A buffer filled by a helper through its pointer parameter (C style), read
// at neighbours after the call.
static void fill_squares(double* t, const double* a, int n) {
  for (int i = 0; i < n; ++i)
    t[i] = a[i] * a[i];
}
DPGEN_KERNEL void filled_by_helper(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double sq[100];
  fill_squares(sq, a, n);
  for (int i = 1; i < n - 1; ++i)
    out[i] = sq[i - 1] - sq[i + 1];
}

// Reads under a condition on the counter that keeps them inside the fill,
// and at the row's ends after the filling loop (straight-line code in the
// row loop).
DPGEN_KERNEL void guarded_and_ends(DPGEN_IN const double* a, DPGEN_OUT double* out,
                                   DPGEN_OUT double* ends, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double t[256];
    for (int i = 0; i < nx - 1; ++i)
      t[i] = std::sin(a[j * nx + i]);
    for (int i = 0; i < nx; ++i)
      if (i > 0)
        out[j * nx + i] = t[i - 1] * a[j * nx + i];
    ends[j] = t[0] + t[nx - 2];
  }
}

// A strided read loop over a buffer (every other element), and a row loop
// that skips its first row with `continue` before the buffer is filled.
DPGEN_KERNEL void strided_skip(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx, int ny) {
  if (nx < 1)
    return;
  for (int j = 0; j < ny; ++j) {
    if (j == 0)
      continue;
    double e[300];
    for (int i = 0; i < nx; ++i)
      e[i] = std::exp(a[j * nx + i] - a[(j - 1) * nx + i]);
    for (int i = 0; i < nx; i += 2)
      out[j * nx + i] = e[i];
  }
}

// Pointers to rows of a constant length over flat parameters (C++ casts).
DPGEN_KERNEL void rows16_cast(DPGEN_IN const double* u_flat, DPGEN_OUT double* o_flat, int ny) {
  const double(*u)[16] = reinterpret_cast<const double(*)[16]>(u_flat);
  double(*o)[16] = (double(*)[16])o_flat;
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < 15; ++i)
      o[j][i] = u[j - 1][i] + u[j + 1][i] - 2.0 * u[j][i] * u[j][i];
}

// A buffer used as scratch within one iteration only (stored, then read back
// at the same element), next to one the kernel declares and never uses.
DPGEN_KERNEL void scratch_same_iteration(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double scratch[100], unused[1000];
  (void)unused;
  for (int i = 0; i < n; ++i) {
    scratch[i] = a[i] * a[i];
    out[i] = scratch[i] + std::cos(scratch[i]);
  }
}
