// adversary: out[0] set before the loop, then overwritten by if (i == n - 1)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_before_loop_overwrite(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  out[0] = 0.5;
  for (int i = 0; i < n; ++i)
    if (i == n - 1) out[0] = a[i] * b[i];
}
