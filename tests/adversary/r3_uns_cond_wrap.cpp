// r3: unsigned wrap in a condition: i < n - 2 is true for every i when n < 2 (n - 2 wraps)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_cond_wrap(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = (i < n - 2) ? a[i] * a[i] : 2.0 * a[i];
}
