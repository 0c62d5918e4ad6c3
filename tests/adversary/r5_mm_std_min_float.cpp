// adversary: std::min in a float kernel
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_std_min_float(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  float m = 4.0f;
  for (int i = 0; i < n; ++i) m = std::min(m, a[i] * a[i] + 0.5f * a[i]);
  out[0] = 2.0f * m + m * m;
}
