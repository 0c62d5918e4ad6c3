// adversary: reduce, copy, reset, reduce again
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_reset_reuse(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  const double first = m;
  m = 1.0;
  for (int i = 0; i < n; ++i) m = fmin(m, b[i]);
  out[0] = first * m;
  out[1] = first - m * m;
}
