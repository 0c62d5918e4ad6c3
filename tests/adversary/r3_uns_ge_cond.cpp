// r3: n - 1 - i >= 1 on size_t: the "not last" test, store mirrored
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_ge_cond(DPGEN_IN const double* a, DPGEN_OUT double* o, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) o[n - 1 - i] = (n - 1 - i >= 1) ? a[i] * a[i + 1] : a[i];
}
