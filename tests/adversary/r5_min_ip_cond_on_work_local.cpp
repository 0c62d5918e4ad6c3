// adversary: MINIMAL: in-place update under a condition on a body local read from a work array: the adjoint does not compile ('w' not declared)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_ip_cond_on_work_local(DPGEN_INOUT double* v, DPGEN_OUT double* w, int n) {
  for (int i = 0; i < n; ++i) w[i] = v[i] * 2.0;
  for (int i = 0; i < n; ++i) {
    const double t = w[i];
    if (t > 0.0) v[i] = t * v[i];
  }
}
