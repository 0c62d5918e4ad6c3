// Centered divergence of a 2D velocity (u, v) on a row-major nx-by-ny grid;
// boundary cells are set to zero.
#include "kernels.hpp"

DPGEN_KERNEL void divergence2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                               DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i == 0 || i == nx - 1 || j == 0 || j == ny - 1) {
        div[k] = 0.0;
        continue;
      }
      div[k] = (u[k + 1] - u[k - 1] + v[k + nx] - v[k - nx]) / (2.0 * h);
    }
  }
}
