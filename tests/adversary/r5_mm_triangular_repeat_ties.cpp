// adversary: the same element met several times by a triangular nest (per-occurrence split?)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_triangular_repeat_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
      m = fmax(m, a[i]);
  out[0] = m;
}
