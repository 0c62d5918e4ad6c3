// (u, v) - grad p on a padded block of a MAC grid: the west face of cell c separates c and
// c - 1, the south face c and c - (nx + 2).
#include "halo_kernels.hpp"

DPGEN_KERNEL void mac_subtract_gradient_halo(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                             DPGEN_IN const double* p, DPGEN_OUT double* u_out,
                                             DPGEN_OUT double* v_out, int nx, int ny, double h) {
  for (int j = 1; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const int c = j * (nx + 2) + i;
      u_out[c] = u[c] - (p[c] - p[c - 1]) / h;
      v_out[c] = v[c] - (p[c] - p[c - nx - 2]) / h;
    }
}
