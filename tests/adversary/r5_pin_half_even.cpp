// adversary: if (2 * i == n): an iteration only for even n
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_half_even(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (2 * i == n) out[0] = a[i] * a[i] + a[0];
}
