// adversary: a work array from u[n - 1 - i], then u[i] updated from it
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_reversed_read(DPGEN_INOUT double* u, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[n - 1 - i] * u[i];
  for (int i = 0; i < n; ++i) u[i] = w[i] + 0.5 * u[i];
}
