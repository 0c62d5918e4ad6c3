// r3: statement-level if on an unsigned wrap: i + 1 - 2 < n is false at i = 0
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_if_store(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    if (i + 1 - 2 < n) o[i] = a[i] * a[i - 1];
    else o[i] = 5.0 * a[i];
  }
}
