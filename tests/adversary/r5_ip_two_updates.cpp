// adversary: two pointwise update loops in turn (the second reads the first's new values)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_two_updates(DPGEN_INOUT double* u, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * u[i];
  for (int i = 0; i < n; ++i) u[i] = u[i] + 1.0;
}
