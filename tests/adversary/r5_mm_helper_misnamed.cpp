// adversary: a helper called vmax that returns the min
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline double vmax(double x, double y) { return x < y ? x : y; }
DPGEN_KERNEL void r5_mm_helper_misnamed(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 3.0;
  for (int i = 0; i < n; ++i) m = vmax(m, a[i]);
  out[0] = m * m;
}
