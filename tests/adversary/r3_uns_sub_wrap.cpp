// r3: unsigned counter with a[i - 1u] reads and n - i store
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_sub_wrap(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 1u; i < n; ++i) o[n - i] = a[i - 1u] * a[i] + a[n - i];
}
