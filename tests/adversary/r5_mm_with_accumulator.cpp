// adversary: a max and a sum in one loop, divided after
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_with_accumulator(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * a[i];
    m = fmax(m, fabs(a[i]));
  }
  out[0] = m / s;
}
