// r3: float work array, sqrtf-style std::sqrt on float, long size
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
DPGEN_KERNEL void r3_float_work_sqrt(DPGEN_IN const float* a, DPGEN_OUT float* w, DPGEN_OUT float* o, long n) {
  for (long i = 0; i < n; ++i) w[i] = std::sqrt(1.0f + a[i] * a[i]);
  for (long i = 1; i < n; ++i) o[i] = w[i] - w[i - 1];
}
