// adversary: a cyclic shift in place through a work array (the update does not read u)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_cyclic_shift(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i == n - 1 ? 0 : i + 1];
  for (int i = 0; i < n; ++i) u[i] = w[i] * w[i];
}
