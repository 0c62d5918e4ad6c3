// adversary: if (e <= m) m = e; (min)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_le_min(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 0.3;
  for (int i = 0; i < n; ++i)
    if (a[i] * a[i] <= m) m = a[i] * a[i];
  out[0] = std::exp(0.5 * m);
}
