// r3 minimal: std::min(i - 1, n - 1) on size_t is n - 1 at i = 0 (wrap); dpgen takes the signed min (-1)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_szt_min_wrap(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) o[i] = a[std::min(i - 1, n - 1)];
}
