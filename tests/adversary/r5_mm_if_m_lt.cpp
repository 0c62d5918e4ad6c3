// adversary: if (m < e) m = e; with fabs
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_if_m_lt(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -0.3;
  for (int i = 0; i < n; ++i)
    if (m < std::fabs(a[i] - b[i])) m = std::fabs(a[i] - b[i]);
  out[0] = std::exp(0.5 * m);
}
