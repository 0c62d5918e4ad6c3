// One weighted-Jacobi sweep for -lap(x) = b, out of place, with a leading
// guard on the grid size.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void jacobi2d_guard(DPGEN_IN const double* x, DPGEN_IN const double* b,
                                 DPGEN_OUT double* x_new, int nx, int ny, double h2,
                                 double omega) {
  if (nx < 3 || ny < 3)
    return;
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int c = j * nx + i;
      double jac = 0.25 * (x[c - 1] + x[c + 1] + x[c - nx] + x[c + nx] + h2 * b[c]);
      x_new[c] = (1.0 - omega) * x[c] + omega * jac;
    }
}
