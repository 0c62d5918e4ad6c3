// adversary: max in a loop counting down
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_countdown(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -2.0;
  int i;
  for (i = n - 1; i >= 0; i--) m = fmax(m, a[i] * (1.0 + a[i]));
  out[0] = m;
}
