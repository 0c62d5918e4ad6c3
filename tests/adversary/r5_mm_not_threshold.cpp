// adversary: if (e > m + 0.1) m = e: a jump recurrence, not a max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_threshold(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m + 0.1) m = a[i];
  out[0] = m * m;
}
