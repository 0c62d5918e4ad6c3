// r3: the unsigned wrap-around count-down for (unsigned i = n - 1; i < n; --i)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_wrap_countdown(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = n - 1; i < n; --i) o[i] = a[i] * a[n - 1 - i];
}
