// adversary: double max over float data in a float kernel
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_double_local_float_data(DPGEN_IN const float* a, DPGEN_OUT float* out, int n) {
  double m = -2.0;
  for (int i = 0; i < n; ++i) m = std::max(m, (double)a[i] * a[i]);
  out[0] = (float)(0.5 * m);
}
