// adversary: m = fmax(fmax(m, a[i]), b[i]): two updates in one expression
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_nested_fmax_fmax(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(fmax(m, a[i]), b[i] * b[i]);
  out[0] = m * m;
}
