// adversary: for (size_t i = n; i-- > 0;) if (i == 0) out[0] = ...
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#include <cstddef>

DPGEN_KERNEL void r5_pin_unsigned_countdown(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, std::size_t n) {
  for (std::size_t i = n; i-- > 0;) {
    u[i] = a[i] * a[i];
    if (i == 0) out[0] = a[0] + a[n - 1];
  }
}
