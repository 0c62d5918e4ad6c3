// adversary: the update reads u[i] and a work array from u[i + 1] and u[i - 1]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_old_in_update_and_work(DPGEN_INOUT double* u, DPGEN_IN const double* k, DPGEN_OUT double* g, int n) {
  for (int i = 1; i < n - 1; ++i) g[i] = k[i] * (u[i + 1] - 2.0 * u[i] + u[i - 1]);
  for (int i = 1; i < n - 1; ++i) u[i] = u[i] * std::exp(-0.1 * g[i]);
}
