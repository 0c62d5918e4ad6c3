// r3: (double)(i - n / 2) with unsigned i, n: wraps to ~4.29e9 for i < n / 2 in the forward
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_cast_center(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = a[i] * a[i] * (1e-9 * (double)(i - n / 2));
}
