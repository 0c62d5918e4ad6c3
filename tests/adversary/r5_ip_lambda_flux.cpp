// adversary: fluxes through a lambda, then the update
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_lambda_flux(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  auto flx = [&](int i) { return 0.5 * (u[i] * u[i] + u[i + 1] * u[i + 1]); };
  for (int i = 0; i + 1 < n; ++i) f[i] = flx(i);
  for (int i = 1; i + 1 < n; ++i) u[i] -= 0.1 * (f[i] - f[i - 1]);
}
