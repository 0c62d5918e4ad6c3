// r3: std::min(i - 1, n - 1) with size_t: at i = 0, i - 1 wraps, so the min is n - 1 (a periodic left neighbour)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_szt_min_wrap(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) o[i] = a[std::min(i - 1, n - 1)] * a[i];
}
