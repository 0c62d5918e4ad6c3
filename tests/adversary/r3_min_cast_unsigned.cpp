// r3 minimal: the (unsigned)k < (unsigned)n bounds idiom on int k, n; dpgen ignores the casts
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_cast_unsigned(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = (unsigned)(i - 1) < (unsigned)n ? a[i - 1] : a[i];
}
