// Gradient with two outputs: centered inside, one-sided at the boundary.
#include "test_kernels.hpp"

DPGEN_KERNEL void gradient2d(DPGEN_IN const double* p, DPGEN_OUT double* gx,
                             DPGEN_OUT double* gy, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int k = j * nx + i;
      if (i == 0)
        gx[k] = (p[k + 1] - p[k]) / h;
      else if (i == nx - 1)
        gx[k] = (p[k] - p[k - 1]) / h;
      else
        gx[k] = (p[k + 1] - p[k - 1]) / (2.0 * h);
      if (j == 0)
        gy[k] = (p[k + nx] - p[k]) / h;
      else if (j == ny - 1)
        gy[k] = (p[k] - p[k - nx]) / h;
      else
        gy[k] = (p[k + nx] - p[k - nx]) / (2.0 * h);
    }
}
