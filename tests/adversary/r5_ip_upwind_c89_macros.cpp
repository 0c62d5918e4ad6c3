// adversary: fluxes from the old rho (C89, macros), then rho updated in place on the interior
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define UP(u, l, r) ((u) > 0.0 ? (u) * (l) : (u) * (r))

DPGEN_KERNEL void r5_ip_upwind_c89_macros(DPGEN_INOUT double* rho, DPGEN_IN const double* u, DPGEN_OUT double* flux, int n, double dt) {
  int i;
  for (i = 1; i < n; i++)
    flux[i] = UP(u[i], rho[i - 1], rho[i]);
  for (i = 1; i < n - 1; i++)
    rho[i] = rho[i] - dt * (flux[i + 1] - flux[i]);
}
