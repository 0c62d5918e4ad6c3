// adversary: if (a[i] > m) m = b[i]: compares one value, keeps another (a recurrence)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_cmp_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m) m = b[i];
  out[0] = m;
}
