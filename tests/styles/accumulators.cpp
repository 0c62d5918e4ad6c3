// Scalar accumulators the way codes write them (issue 20): a running sum in a
// local, read after its loop. Each becomes a hidden work array the adjoint
// recomputes; the sum's use after the loop may be nonlinear.
#include "dpgen/annotate.hpp"

#include <cmath>

// The 2-norm: sum, then sqrt of it, in a local.
DPGEN_KERNEL void acc_norm2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    s += a[i] * a[i];
  const double norm = std::sqrt(s);
  out[0] = norm;
}

// Per-row sums, the local declared in the row loop.
DPGEN_KERNEL void acc_rowsum(DPGEN_IN const double* a, DPGEN_OUT double* row, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double s = 0;
    for (int i = 0; i < nx; ++i)
      s += a[j * nx + i];
    row[j] = s * s;
  }
}

// C89: counters and the sum declared at the top, `s = s + ...`, a constant
// weight array, the mean per row.
DPGEN_KERNEL void acc_rowmean_c89(DPGEN_IN const double* a, const double* w, DPGEN_OUT double* m,
                                  int nx, int ny) {
  int i, j;
  double s;
  for (j = 0; j < ny; j++) {
    s = 0.0;
    for (i = 0; i < nx; i++)
      s = s + w[i] * a[j * nx + i];
    m[j] = s / nx;
  }
}

// A dot product in float, the sum starting from a bias.
DPGEN_KERNEL void acc_dot_float(DPGEN_IN const float* x, DPGEN_IN const float* y,
                                DPGEN_OUT float* out, int n, float bias) {
  float s = bias;
  for (int i = 0; i < n; ++i)
    s += x[i] * y[i];
  out[0] = s;
}

// Normalization: the total, then every element divided by it in a later loop.
DPGEN_KERNEL void acc_normalize(DPGEN_IN const double* u, DPGEN_OUT double* p, int n) {
  double total = 1.0;
  for (int i = 0; i < n; ++i)
    total += u[i] * u[i];
  for (int i = 0; i < n; ++i)
    p[i] = u[i] / total;
}

// Two sums in one loop, one of them subtracting, combined after it.
DPGEN_KERNEL void acc_two_sums(DPGEN_IN const double* a, DPGEN_IN const double* b,
                               DPGEN_OUT double* out, int n) {
  double sa = 0, sb = 0;
  for (int i = 1; i < n; ++i) {
    sa += a[i] * b[i - 1];
    sb -= std::exp(0.1 * b[i]);
  }
  out[0] = sa * sb;
  out[1] = sa + std::tanh(sb);
}

// Column sums of a 3D block into a 2D plane: the sum per (j, i), over k.
DPGEN_KERNEL void acc_column(DPGEN_IN const double* a, DPGEN_OUT double* col, int nx, int ny,
                             int nz) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double s = 0.0;
      for (int k = 0; k < nz; ++k)
        s += a[(k * ny + j) * nx + i] * (k + 1);
      col[j * nx + i] = std::sqrt(1.0 + s * s);
    }
}
