// adversary: if (e > m && i > 0) m = e;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_and_cond(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m && i > 0) m = a[i];
  out[0] = m * m;
}
