// -Laplacian, 5-point, on a padded block: the pressure Poisson operator (div of grad).
#include "halo_kernels.hpp"

DPGEN_KERNEL void neg_laplacian_halo2d(DPGEN_IN const double* p, DPGEN_OUT double* out, int nx,
                                       int ny, double h) {
  for (int j = 1; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const int c = j * (nx + 2) + i;
      const double sum = p[c + 1] + p[c - 1] + p[c + nx + 2] + p[c - nx - 2];
      out[c] = (4.0 * p[c] - sum) / (h * h);
    }
}
