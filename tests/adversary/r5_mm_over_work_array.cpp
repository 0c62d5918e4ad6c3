// adversary: max over a work array (DPGEN_OUT) filled by an earlier loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_over_work_array(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* w, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) w[i] = a[i] * a[i] - b[i];
  double m = -5.0;
  for (int i = 0; i < n; ++i) m = fmax(m, w[i]);
  out[0] = m * m;
}
