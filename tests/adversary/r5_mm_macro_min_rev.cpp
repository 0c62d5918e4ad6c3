// adversary: MIN macro, element first
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define MIN(x, y) (((x) < (y)) ? (x) : (y))

DPGEN_KERNEL void r5_mm_macro_min_rev(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 5.0;
  int i;
  for (i = 0; i < n; i++) m = MIN(a[i] - 2.0 * b[i], m);
  out[0] = m * m;
}
