// adversary: MINIMAL: in-place update under a condition on a max reduction of the old values: the adjoint does not compile (dpgen_max_m not declared)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_ip_cond_on_max(DPGEN_INOUT double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, v[i]);
  for (int i = 0; i < n; ++i)
    if (v[i] > 0.5 * m) v[i] = v[i] * v[i];
}
