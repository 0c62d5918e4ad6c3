// -div(k grad p) on a padded nx-by-ny block, face coefficients (k[c] + k[m]) / 2: the same sums
// in the same order as tests/runtime/operators/neg_div_k_grad_periodic2d.cpp.
#include "halo_kernels.hpp"

DPGEN_KERNEL void neg_div_k_grad_halo2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                        DPGEN_OUT double* out, int nx, int ny, double h) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 1; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const int c = j * (nx + 2) + i;
      const int e = c + 1, w = c - 1, no = c + nx + 2, so = c - nx - 2;
      double sum = 0.5 * (k[c] + k[e]) * (p[c] - p[e]);
      sum += 0.5 * (k[c] + k[w]) * (p[c] - p[w]);
      sum += 0.5 * (k[c] + k[no]) * (p[c] - p[no]);
      sum += 0.5 * (k[c] + k[so]) * (p[c] - p[so]);
      out[c] = sum * inv_h2;
    }
}
