// adversary: max of a clamped element fmax(m, fmin(a[i], 0.5))
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_clamp_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -3.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fmin(a[i], 0.5) + 0.1 * a[i]);
  out[0] = m;
}
