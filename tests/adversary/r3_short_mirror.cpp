// r3: short size and counter, mirror read a[n - 1 - i]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_short_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, short n) {
  for (short i = 0; i < n; ++i) o[i] = a[n - 1 - i] * a[i] + a[n - 1 - i];
}
