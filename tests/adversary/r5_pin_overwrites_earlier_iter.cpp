// adversary: if (i == n - 1) u[0] = b[0]; u[i] = a[i]; (the pinned store wins for n >= 2, loses for n = 1)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_overwrites_earlier_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) u[0] = b[0] * 3.0;
    u[i] = a[i] * a[i];
  }
}
