// adversary: a reduction loop under if (flag), read after the if
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_reduce_in_flag_arm(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double m = 0.5;
  if (flag) {
    for (int i = 0; i < n; ++i) m = fmax(m, a[i] * a[i]);
  }
  out[0] = m * m;
}
