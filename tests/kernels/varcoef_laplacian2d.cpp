// div(k grad p) with face coefficients averaged from cell values; boundary
// cells are zero. Differentiable in both the coefficient kc and the field p.
#include "test_kernels.hpp"

DPGEN_KERNEL void varcoef_laplacian2d(DPGEN_IN const double* kc, DPGEN_IN const double* p,
                                      DPGEN_OUT double* out, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      int k = j * nx + i;
      if (i == 0 || j == 0 || i == nx - 1 || j == ny - 1) {
        out[k] = 0.0;
        continue;
      }
      double ke = 0.5 * (kc[k] + kc[k + 1]);
      double kw = 0.5 * (kc[k] + kc[k - 1]);
      double kn = 0.5 * (kc[k] + kc[k + nx]);
      double ks = 0.5 * (kc[k] + kc[k - nx]);
      double flux = ke * (p[k + 1] - p[k]) - kw * (p[k] - p[k - 1]) +
                    kn * (p[k + nx] - p[k]) - ks * (p[k] - p[k - nx]);
      out[k] = flux / (h * h);
    }
}
