// adversary: a max of |v| (min/max reduction) of the old values, then v rescaled in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_normalize_by_max(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(v[i]));
  for (int i = 0; i < n; ++i) v[i] = v[i] / (1.0 + m);
}
