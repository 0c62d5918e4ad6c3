// r3: size_t counter from 2, store o[i - 2], reads a[i], a[i - 2]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_szt_shift_store(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 2; i < n; ++i) o[i - 2] = a[i] * a[i - 2] - a[i - 1];
}
