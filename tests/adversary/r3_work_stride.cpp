// r3: work array of 2n read pairwise o[i] = w[2i] * w[2i+1]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_work_stride(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < 2 * n; ++i) w[i] = std::sin(a[i]);
  for (int i = 0; i < n; ++i) o[i] = w[2 * i] * w[2 * i + 1] + a[2 * i];
}
