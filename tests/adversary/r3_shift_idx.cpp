// r3: bit operations in indices: a[i >> 1], (i & 1) parity
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_shift_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = (i & 1) ? a[i >> 1] * a[i] : a[i] - a[i >> 1];
}
