// corpus: form=scalarref expect=accept
// A scalar output by reference (double& mass) and constant inputs by const
// reference. Adjoint: total_mass_adjoint(rho, rho_adj, nx, ny, dx, dy, double mass_adj).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void total_mass(DPGEN_IN const double* rho, int nx, int ny, const double& dx,
                             const double& dy, DPGEN_OUT double& mass) {
  mass = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      mass += rho[j * nx + i] * dx * dy;
}
