// adversary: the max read inside its own loop through a pinned store if (i == n - 1) out[0] = m
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_read_in_pinned(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) {
    m = fmax(m, a[i]);
    if (i == n - 1) out[0] = m;
  }
}
