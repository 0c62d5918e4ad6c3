// r3: clamped indices in long: std::min<long>(i + 2, n - 1), size_t n
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_clamp_long(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  const long nn = (long)n;
  for (long i = 0; i < nn; ++i) o[i] = a[std::min<long>(i + 2, nn - 1)] - a[i] * a[std::max<long>(i - 2, 0)];
}
