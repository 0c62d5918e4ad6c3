// adversary: fluxes from the old values, then a conditional update in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_cond_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i + 1 < n; ++i) f[i] = u[i + 1] * u[i + 1] - u[i];
  for (int i = 0; i + 1 < n; ++i)
    if (f[i] > 0.0) u[i] -= 0.25 * f[i];
}
