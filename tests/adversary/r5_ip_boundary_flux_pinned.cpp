// adversary: fluxes with boundary values pinned to the first/last iterations, then the update
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_boundary_flux_pinned(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i <= n; ++i) {
    if (i == 0) f[0] = u[0] * u[0];
    else if (i == n) f[n] = -u[n - 1];
    else f[i] = 0.5 * (u[i] - u[i - 1]);
  }
  for (int i = 0; i < n; ++i) u[i] -= 0.2 * (f[i + 1] - f[i]);
}
