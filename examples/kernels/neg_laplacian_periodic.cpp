// -Laplacian, 5-point, periodic: symmetric positive semi-definite, with the
// constants as its null space (the pressure Poisson operator, div of grad).
#include "example_kernels.hpp"

DPGEN_KERNEL void neg_laplacian_periodic(DPGEN_IN const double* p, DPGEN_OUT double* out,
                                         int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ie = i == nx - 1 ? 0 : i + 1, iw = i == 0 ? nx - 1 : i - 1;
      const int jn = j == ny - 1 ? 0 : j + 1, js = j == 0 ? ny - 1 : j - 1;
      const double sum = p[j * nx + ie] + p[j * nx + iw] + p[jn * nx + i] + p[js * nx + i];
      out[j * nx + i] = (4.0 * p[j * nx + i] - sum) / (h * h);
    }
}
