// First-order upwind advection on a block of n cells with one halo cell on each side: the
// same arithmetic as kernels/upwind_step.cpp, with the periodic wrap left to the halo exchange.
#include "halo_kernels.hpp"

#include <algorithm>

DPGEN_KERNEL void upwind_step_halo(DPGEN_IN const double* d, DPGEN_IN const double* u,
                                   DPGEN_OUT double* d_next, int n, double dt, double dx) {
  for (int i = 1; i <= n; ++i) {
    const double up = std::min(u[i] / dx, 0.0);
    const double um = std::max(u[i] / dx, 0.0);
    d_next[i] = d[i] - dt * (up * (d[i + 1] - d[i]) + um * (d[i] - d[i - 1]));
  }
}
