// r3 minimal: unsigned n - 2 wraps at n = 1, so i < n - 2 is true there; dpgen evaluates it signed (false)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_uns_cond_wrap(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = i < n - 2 ? a[i] : 2.0 * a[i];
}
