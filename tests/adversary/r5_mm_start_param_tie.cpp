// adversary: start from a parameter, ties with it
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_start_param_tie(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, double lo) {
  double m = lo;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  out[0] = m * m * m;
}
