// r3: unsigned i <= n - 1 (n >= 1), read a[n - 1 - i] and a[i / 2]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_le_nm1(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i <= n - 1; ++i) o[i] = a[n - 1 - i] * a[i] - a[i];
}
