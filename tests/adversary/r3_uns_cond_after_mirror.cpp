// r3: mirror read of a conditionally overwritten value with unsigned size
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_cond_after_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    double v = a[n - 1 - i];
    if (i < n / 2) v = v * a[i];
    o[i] = v;
  }
}
