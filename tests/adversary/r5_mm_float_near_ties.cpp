// adversary: float products that tie only after float rounding
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_float_near_ties(DPGEN_IN const float* a, DPGEN_IN const float* b, DPGEN_OUT float* out, int n) {
  float m = -2.0f;
  for (int i = 0; i < n; ++i) m = fmaxf(m, a[i] * b[i]);
  out[0] = 2.0f * m;
}
