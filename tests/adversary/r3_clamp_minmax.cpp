// r3: clamped indices std::min(i + 1, n - 1), std::max(i - 1, 0)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_clamp_minmax(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = a[std::min(i + 1, n - 1)] * a[std::max(i - 1, 0)] + a[i];
}
