// adversary: MINIMAL: a void helper assigning a kernel-level local through a reference inside a loop; the local read after the loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline void setv(double& s, double e) { s = e; }
DPGEN_KERNEL void r5_min_helper_ref_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) setv(s, a[i] * a[i]);
  out[0] = s;
}
