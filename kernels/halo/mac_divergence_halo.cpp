// Divergence on a padded block of a MAC grid: (u east - u west + v north - v south) / h, where
// the east (north) face of a cell is the west (south) face of the next one.
#include "halo_kernels.hpp"

DPGEN_KERNEL void mac_divergence_halo(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                      DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 1; j <= ny; ++j)
    for (int i = 1; i <= nx; ++i) {
      const int c = j * (nx + 2) + i;
      div[c] = (u[c + 1] - u[c] + v[c + nx + 2] - v[c]) / h;
    }
}
