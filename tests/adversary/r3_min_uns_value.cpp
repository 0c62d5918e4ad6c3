// r3 minimal: (double)(i - n) with unsigned i < n is 2^32 - (n - i) in the forward; dpgen: negative
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_uns_value(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = 1e-9 * (double)(i - n) * a[i];
}
