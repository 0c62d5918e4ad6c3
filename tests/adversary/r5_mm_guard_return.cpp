// adversary: if (n < 1) return; m = -HUGE_VAL
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_guard_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  if (n < 1) return;
  double m = -HUGE_VAL;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
  out[0] = m;
}
