// Variable-conductivity 2D heat step in flux form (arithmetic face means),
// every pointer __restrict-qualified.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat2d_restrict(DPGEN_IN const double* __restrict t,
                                  DPGEN_IN const double* __restrict kappa,
                                  DPGEN_OUT double* __restrict t_new, int nx, int ny,
                                  double dt_h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int c = j * nx + i;
      const double fe = 0.5 * (kappa[c] + kappa[c + 1]) * (t[c + 1] - t[c]);
      const double fw = 0.5 * (kappa[c] + kappa[c - 1]) * (t[c] - t[c - 1]);
      const double fn = 0.5 * (kappa[c] + kappa[c + nx]) * (t[c + nx] - t[c]);
      const double fs = 0.5 * (kappa[c] + kappa[c - nx]) * (t[c] - t[c - nx]);
      t_new[c] = t[c] + dt_h2 * (fe - fw + fn - fs);
    }
}
