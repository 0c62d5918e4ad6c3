// adversary: for (size_t j = n; j-- > 0;) { K[j] = f; K[j + 1] = g; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include <cstddef>

DPGEN_KERNEL void r5_lw_unsigned_countdown(DPGEN_IN const double* a, DPGEN_OUT double* K, std::size_t n) {
  for (std::size_t j = n; j-- > 0;) {
    K[j] = a[j] * a[j];
    K[j + 1] = std::sin(a[j]);
  }
}
