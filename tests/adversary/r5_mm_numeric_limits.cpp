// adversary: m = std::numeric_limits<double>::lowest()
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include <limits>

DPGEN_KERNEL void r5_mm_numeric_limits(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = std::numeric_limits<double>::lowest();
  for (int i = 0; i < n; ++i) m = std::max(m, a[i] * a[i]);
  out[0] = m;
}
