// adversary: if (i == n - 1) { out[0] = a[i]; out[0] = out[0] * out[0]; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_readback(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    if (i == n - 1) {
      out[0] = a[i] + 1.0;
      out[0] = out[0] * out[0];
    }
}
