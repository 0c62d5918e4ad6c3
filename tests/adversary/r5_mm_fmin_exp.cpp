// adversary: fmin of a difference, exp after
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_fmin_exp(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = 10.0;
  for (int i = 0; i < n; ++i) m = fmin(m, a[i] - b[i]);
  out[0] = std::exp(m);
}
