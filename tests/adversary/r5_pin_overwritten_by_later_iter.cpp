// adversary: u[i] = a[i]; if (i == 0) u[n - 1] = b[0]; (iteration n - 1 overwrites it for n >= 2)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_overwritten_by_later_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    if (i == 0) u[n - 1] = b[0] * 3.0;
  }
}
