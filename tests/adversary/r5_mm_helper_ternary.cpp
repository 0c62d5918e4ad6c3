// adversary: m = mymax(m, e), a user helper returning a ?: max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline double mymax(double x, double y) { return x > y ? x : y; }
DPGEN_KERNEL void r5_mm_helper_ternary(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = mymax(m, a[i] * b[i]);
  out[0] = m * m;
}
