// adversary: fluxes from all of u, then every other element updated in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_strided_update(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i + 1 < n; ++i) f[i] = u[i + 1] - u[i];
  for (int i = 0; i + 1 < n; i += 2) u[i] = u[i] * (1.0 + f[i]);
}
