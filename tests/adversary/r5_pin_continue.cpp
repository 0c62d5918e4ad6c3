// adversary: if (i == 0) { out[0] = ...; continue; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_continue(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0) { out[0] = std::exp(a[0]); continue; }
    u[i] = a[i] * a[i - 1];
  }
}
