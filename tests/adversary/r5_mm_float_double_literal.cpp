// adversary: float max of a float times a double literal (the element is a double, m a float)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_float_double_literal(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = -2.0f;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * 0.1);
  out[0] = 10.0f * m;
}
