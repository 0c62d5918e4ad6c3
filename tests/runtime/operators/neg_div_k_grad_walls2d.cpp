// -div(k grad p) on an nx-by-ny grid with walls: face coefficients (k[c] + k[m]) / 2
// inside; on a wall face the flux is wall * k[c] * p[c] / h^2, with wall = 0 for
// Neumann (ghost = p[c]) and wall = 2 for Dirichlet (ghost = -p[c], zero on the face).
#include "operators.hpp"

DPGEN_KERNEL void neg_div_k_grad_walls2d(DPGEN_IN const double* p, DPGEN_IN const double* k,
                                         DPGEN_OUT double* out, int nx, int ny, double h,
                                         double west, double east, double south, double north) {
  const double inv_h2 = 1.0 / (h * h);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int c = j * nx + i;
      double sum = i < nx - 1 ? 0.5 * (k[c] + k[c + 1]) * (p[c] - p[c + 1]) : east * k[c] * p[c];
      sum += i > 0 ? 0.5 * (k[c] + k[c - 1]) * (p[c] - p[c - 1]) : west * k[c] * p[c];
      sum += j < ny - 1 ? 0.5 * (k[c] + k[c + nx]) * (p[c] - p[c + nx]) : north * k[c] * p[c];
      sum += j > 0 ? 0.5 * (k[c] + k[c - nx]) * (p[c] - p[c - nx]) : south * k[c] * p[c];
      out[c] = sum * inv_h2;
    }
}
