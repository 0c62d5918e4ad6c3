// adversary: max under an index condition; an excluded element equals the max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_cond_index_path_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -9.0;
  for (int i = 0; i < n; ++i)
    if (i % 2 == 0) m = fmax(m, a[i]);
  out[0] = m * m;
}
