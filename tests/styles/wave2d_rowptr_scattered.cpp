// A variable-speed wave/diffusion update on `double**` grids whose rows are
// allocated one by one (`u[j] = new double[nx]`), C89 counters. dpgen takes
// the row pointers as they are: the adjoint and tangent index them [j][i].
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void wave2d_rowptr_scattered(DPGEN_IN double** u, DPGEN_IN double** c,
                                          DPGEN_OUT double** un, int nx, int ny, double dt) {
  int i, j;
  double lap;
  for (j = 1; j < ny - 1; j++) {
    for (i = 1; i < nx - 1; i++) {
      lap = u[j][i + 1] + u[j][i - 1] + u[j + 1][i] + u[j - 1][i] - 4.0 * u[j][i];
      un[j][i] = u[j][i] + dt * c[j][i] * c[j][i] * lap;
    }
  }
}
