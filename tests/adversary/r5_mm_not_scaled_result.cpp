// adversary: m = 0.9 * fmax(m, a[i]): not a plain max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_not_scaled_result(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = 0.9 * fmax(m, a[i]);
  out[0] = m;
}
