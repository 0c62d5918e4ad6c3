// adversary: a work array from u, an accumulator over the work array, then u updated from both
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_work_accum_between(DPGEN_INOUT double* u, DPGEN_IN const double* a, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = u[i] * a[i];
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += w[i] * w[i];
  for (int i = 0; i < n; ++i) u[i] = u[i] - 0.1 * s * w[i];
}
