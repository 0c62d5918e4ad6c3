#include "dpgen/annotate.hpp"
#include <algorithm>
DPGEN_KERNEL void clamp_minmax(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[std::min(i + 1, n - 1)] * a[std::max(i - 1, 0)];
}
