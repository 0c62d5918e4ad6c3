// r3: ternary on an index condition picks mirror or identity
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_ternary_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = (i < n / 2) ? a[i] * a[n - 1 - i] : a[i] * 3.0;
}
