// adversary: MINIMAL: a void helper summing into a kernel-level local through a pointer inside a loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline void addp(double* s, double e) { *s += e; }
DPGEN_KERNEL void r5_min_helper_ptr_accum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) addp(&s, a[i] * a[i]);
  out[0] = s;
}
