// adversary: start 0 ties with a zero element
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_start_const_tie(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double e = 0.0;
  for (int i = 0; i < n; ++i) e = fmax(e, a[i] - b[i]);
  out[0] = 2.0 * e + 1.0;
}
