/* Variable-coefficient Poisson residual, 3D, interior only. C89: all
   counters and the flat index declared at function scope; face
   coefficients are arithmetic means of the cell values. */
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void varcoef_poisson3d_c89(DPGEN_IN const double* kappa, DPGEN_IN const double* u,
                                        DPGEN_OUT double* r, int nx, int ny, int nz)
{
  int i, j, k, c;
  int nxy;
  nxy = nx * ny;
  for (k = 1; k < nz - 1; k++)
    for (j = 1; j < ny - 1; j++)
      for (i = 1; i < nx - 1; i++) {
        c = i + nx * j + nxy * k;
        r[c] = 0.5 * (kappa[c] + kappa[c + 1]) * (u[c + 1] - u[c]) -
               0.5 * (kappa[c] + kappa[c - 1]) * (u[c] - u[c - 1]) +
               0.5 * (kappa[c] + kappa[c + nx]) * (u[c + nx] - u[c]) -
               0.5 * (kappa[c] + kappa[c - nx]) * (u[c] - u[c - nx]) +
               0.5 * (kappa[c] + kappa[c + nxy]) * (u[c + nxy] - u[c]) -
               0.5 * (kappa[c] + kappa[c - nxy]) * (u[c] - u[c - nxy]);
      }
}
