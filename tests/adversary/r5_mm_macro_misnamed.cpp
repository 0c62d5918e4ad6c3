// adversary: a macro named MAX that is a min: dpgen must compute the min
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define MAX(x, y) ((x) < (y) ? (x) : (y))

DPGEN_KERNEL void r5_mm_macro_misnamed(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 3.0;
  for (int i = 0; i < n; ++i) m = MAX(m, a[i]);
  out[0] = m * m;
}
