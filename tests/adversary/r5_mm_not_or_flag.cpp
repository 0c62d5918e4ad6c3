// adversary: if (e > m || flag) m = e: with flag set it is the last element
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_or_flag(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double m = -3.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > m || flag) m = a[i];
  out[0] = m * m;
}
