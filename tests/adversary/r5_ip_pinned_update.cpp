// adversary: a sum of the old values, then only u[0] updated (pinned store in the update loop)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_pinned_update(DPGEN_INOUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += u[i] * u[i];
  for (int i = 0; i < n; ++i)
    if (i == 0) u[0] = s;
}
