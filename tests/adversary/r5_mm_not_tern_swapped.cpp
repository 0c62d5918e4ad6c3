// adversary: m = (e > m) ? m : e is a min; m = (e > m) ? e : e is not a reduction... here: (m > e) ? m : 2*e
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_tern_swapped(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = (m > a[i]) ? m : 2.0 * a[i];
  out[0] = m;
}
