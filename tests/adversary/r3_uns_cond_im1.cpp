// r3: unsigned i - 1 < n as the "has a left neighbour" test (false at i = 0 by wrap-around)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_cond_im1(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = (i - 1 < n) ? a[i - 1] * a[i] : 3.0 * a[i];
}
