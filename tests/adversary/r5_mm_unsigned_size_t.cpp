// adversary: size_t counter and size
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include <cstddef>

DPGEN_KERNEL void r5_mm_unsigned_size_t(DPGEN_IN const double* a, DPGEN_OUT double* out, std::size_t n) {
  double m = 100.0;
  for (std::size_t i = 0; i < n; ++i) m = std::min(m, a[i] * a[i] - a[i]);
  out[0] = m;
}
