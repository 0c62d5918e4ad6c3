// adversary: a loop reads u after the loop that updated it
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_read_after_update(DPGEN_INOUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * u[i];
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += u[i];
  out[0] = s;
}
