// r3: unsigned size, int local mirror index m = n - 1 - i used for store and read
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_local_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    const int m = n - 1 - i;
    o[m] = a[m] * a[i] + 2.0 * a[m];
  }
}
