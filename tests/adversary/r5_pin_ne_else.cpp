// adversary: if (i != 0) {...} else out[0] = ...
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_ne_else(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i != 0) u[i] = a[i] - a[i - 1];
    else out[0] = a[0] * a[0];
  }
}
