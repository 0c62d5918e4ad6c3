// r3: size_t i-- > 0 countdown with mirror read
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_countdown_szt_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = n; i-- > 0;) o[i] = a[n - 1 - i] * a[i] + a[i];
}
