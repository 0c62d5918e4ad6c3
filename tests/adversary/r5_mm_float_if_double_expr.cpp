// adversary: if (a[i] * 0.1 < m) m = a[i] * 0.1; in a float kernel
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_float_if_double_expr(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = 2.0f;
  for (int i = 0; i < n; ++i)
    if (a[i] * 0.1 < m) m = a[i] * 0.1;
  out[0] = 10.0f * m;
}
