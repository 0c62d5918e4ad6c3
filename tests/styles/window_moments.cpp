// window_moments (tests/styles/): sums over a window of run-time half-width
// d inside the cell loops (issue 22: local_variance), read after their loop:
// the adjoint recomputes them into buffers indexed like the output, whose
// row length nx the loops bound only by nx >= 2 * d + 1 (d may be negative
// as far as the kernel says), so the buffer's extent assumes nx >= 0 and the
// generated code checks it on entry.
#include "dpgen/annotate.hpp"

#include <cmath>

// The second central moment per cell over a row window of 2 * d + 1 cells.
DPGEN_KERNEL void window_moments(DPGEN_IN const double* a, DPGEN_OUT double* m2, int nx, int ny,
                                 int d) {
  for (int j = 0; j < ny; ++j)
    for (int i = d; i < nx - d; ++i) {
      double s = 0.0, s2 = 0.0;
      for (int ii = i - d; ii <= i + d; ++ii) {
        s += a[j * nx + ii];
        s2 += a[j * nx + ii] * a[j * nx + ii];
      }
      m2[j * nx + i] = s2 - s * s / (2 * d + 1);
    }
}

// A windowed maximum-free smoothing over columns: each cell's mean of its
// column window, then exp of it (a sum read after its loop, a nonlinear use).
DPGEN_KERNEL void window_column_exp(DPGEN_IN const double* a, DPGEN_OUT double* out, int nx,
                                    int ny, int d) {
  for (int j = d; j < ny - d; ++j)
    for (int i = 0; i < nx; ++i) {
      double s = 0.0;
      for (int jj = j - d; jj <= j + d; ++jj)
        s += a[jj * nx + i];
      out[j * nx + i] = std::exp(0.2 * s);
    }
}
