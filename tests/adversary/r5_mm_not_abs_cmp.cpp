// adversary: if (fabs(a[i]) > m) m = a[i]: compares |a|, keeps a
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_abs_cmp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i)
    if (std::fabs(a[i]) > m) m = a[i];
  out[0] = m * m + m;
}
