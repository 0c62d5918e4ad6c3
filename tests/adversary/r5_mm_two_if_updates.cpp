// adversary: if (a[i] > m) m = a[i]; if (b[i] > m) m = b[i];
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_two_if_updates(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    if (a[i] > m) m = a[i];
    if (b[i] * b[i] > m) m = b[i] * b[i];
  }
  out[0] = m;
}
