// adversary: if (i == 5): no such iteration for n <= 5
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_const_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 5) out[0] = a[i] * a[i - 1];
}
