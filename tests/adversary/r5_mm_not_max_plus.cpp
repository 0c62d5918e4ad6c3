// adversary: m = fmax(m + 0.1, a[i])
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_max_plus(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m + 0.1, a[i]);
  out[0] = m;
}
