// -div(k grad p), periodic, face coefficients (k[c] + k[m]) / 2.
#include "operators.hpp"

DPGEN_KERNEL void neg_div_k_grad_periodic2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                            DPGEN_OUT double* out, int nx, int ny, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      const int e = j * nx + (i == nx - 1 ? 0 : i + 1);
      const int w = j * nx + (i == 0 ? nx - 1 : i - 1);
      const int no = (j == ny - 1 ? 0 : j + 1) * nx + i;
      const int so = (j == 0 ? ny - 1 : j - 1) * nx + i;
      double sum = 0.5 * (k[c] + k[e]) * (p[c] - p[e]);
      sum += 0.5 * (k[c] + k[w]) * (p[c] - p[w]);
      sum += 0.5 * (k[c] + k[no]) * (p[c] - p[no]);
      sum += 0.5 * (k[c] + k[so]) * (p[c] - p[so]);
      out[c] = sum * inv_h2;
    }
}
