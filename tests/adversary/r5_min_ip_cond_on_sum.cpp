// adversary: MINIMAL: in-place update under a condition on an accumulator of the old values: the adjoint does not compile (dpgen_sum_s not declared)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_ip_cond_on_sum(DPGEN_INOUT double* v, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += v[i] * v[i];
  for (int i = 0; i < n; ++i)
    if (s > 1.0) v[i] = v[i] / s;
}
