// 5-point Laplacian on a row-major nx-by-ny grid; boundary cells are zero.
#include "kernels.hpp"

DPGEN_KERNEL void laplacian2d(DPGEN_IN const double* a, DPGEN_OUT double* out,
                              int nx, int ny, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i == 0 || i == nx - 1 || j == 0 || j == ny - 1) {
        out[k] = 0.0;
      } else {
        out[k] = (a[k - 1] + a[k + 1] + a[k - nx] + a[k + nx] - 4.0 * a[k]) * inv_h2;
      }
    }
  }
}
