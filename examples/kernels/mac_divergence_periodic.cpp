// Divergence on a periodic MAC grid: (u east - u west + v north - v south)/h.
#include "example_kernels.hpp"

DPGEN_KERNEL void mac_divergence_periodic(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                          DPGEN_OUT double* div, int nx, int ny, double h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int ie = i == nx - 1 ? 0 : i + 1; // east face = west face of the next cell
      const int jn = j == ny - 1 ? 0 : j + 1;
      div[j * nx + i] = (u[j * nx + ie] - u[j * nx + i] + v[jn * nx + i] - v[j * nx + i]) / h;
    }
}
