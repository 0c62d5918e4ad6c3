// adversary: m = a[i] > m ? b[i] : m
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_tern_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = a[i] > m ? b[i] : m;
  out[0] = m;
}
