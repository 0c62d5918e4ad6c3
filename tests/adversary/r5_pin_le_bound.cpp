// adversary: for (i = 0; i <= n; i++) if (i == n) out[0] = ...
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_le_bound(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i <= n; i++) {
    u[i] = a[i] * 2.0;
    if (i == n) out[0] = a[i] * a[i];
  }
}
