// adversary: the max starts a later accumulator: s = m; s += a[i]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_start_of_accumulator(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  double s = m;
  for (int i = 0; i < n; ++i) s += a[i] * m;
  out[0] = s * s;
}
