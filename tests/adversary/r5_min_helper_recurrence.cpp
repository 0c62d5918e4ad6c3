// adversary: MINIMAL: a recurrence s = 0.5 s + e hidden in a helper: accepted, the loop dropped
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline void rec(double& s, double e) { s = 0.5 * s + e; }
DPGEN_KERNEL void r5_min_helper_recurrence(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) rec(s, a[i]);
  out[0] = s;
}
