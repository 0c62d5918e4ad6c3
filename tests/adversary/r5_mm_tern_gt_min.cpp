// adversary: min as (m > e) ? e : m
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_tern_gt_min(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 0.25;
  for (int i = 0; i < n; ++i) {
    const double e = a[i] * b[i] - 0.1 * a[i];
    m = (m > e) ? e : m;
  }
  out[0] = m * (1.0 + m);
}
