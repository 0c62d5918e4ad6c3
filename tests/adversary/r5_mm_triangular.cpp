// adversary: max over a triangular nest
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_triangular(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      m = fmax(m, a[i] * a[j] + 0.1 * j);
  out[0] = m;
}
