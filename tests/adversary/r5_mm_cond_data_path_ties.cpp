// adversary: max under a data condition; an excluded element equals the max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_cond_data_path_ties(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (b[i] > 0.0) m = std::max(m, a[i]);
  out[0] = m * m;
}
