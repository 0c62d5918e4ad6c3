// adversary: the element uses a kernel-level local computed from data
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_local_from_data(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  const double c = 1.0 + a[0] * a[0];
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, c * b[i]);
  out[0] = m * c;
}
