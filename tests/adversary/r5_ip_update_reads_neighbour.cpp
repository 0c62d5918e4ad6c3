// adversary: the update loop reads u[i - 1] (Gauss-Seidel)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_update_reads_neighbour(DPGEN_INOUT double* u, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = u[i] * u[i];
  for (int i = 1; i < n; ++i) u[i] = 0.5 * (u[i] + u[i - 1]) + f[i];
}
