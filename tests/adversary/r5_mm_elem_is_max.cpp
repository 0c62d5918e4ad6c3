// adversary: m = fmax(m, fmax(a[i], b[i])): the element itself a max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_elem_is_max(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fmax(a[i], 0.5 * b[i]));
  out[0] = m * m;
}
