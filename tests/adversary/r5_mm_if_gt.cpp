// adversary: if (e > m) m = e;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_gt(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -0.3;
  for (int i = 0; i < n; ++i)
    if (a[i] * b[i] > m) m = a[i] * b[i];
  out[0] = std::exp(0.5 * m);
}
