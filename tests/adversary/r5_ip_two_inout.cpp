// adversary: two in-place arrays exchanging through a work array: f = u - v; u -= f; v += f
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_two_inout(DPGEN_INOUT double* u, DPGEN_INOUT double* v, DPGEN_OUT double* f, int n) {
  for (int i = 0; i < n; ++i) f[i] = 0.5 * (u[i] - v[i]) * u[i];
  for (int i = 0; i < n; ++i) u[i] -= f[i];
  for (int i = 0; i < n; ++i) v[i] += f[i] * v[i];
}
