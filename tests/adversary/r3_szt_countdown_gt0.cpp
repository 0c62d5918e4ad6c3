// r3: for (size_t i = n; i > 0; --i) o[i - 1] = ... with a mirror read a[n - i]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_szt_countdown_gt0(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = n; i > 0; --i) o[i - 1] = a[i - 1] * a[n - i] + a[n - i];
}
