// adversary: fluxes, then the update in a loop counting down
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_countdown_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = u[i] * u[n - 1 - i];
  for (int i = n - 1; i >= 0; --i) u[i] = u[i] + f[i];
}
