// adversary: if (i == 0) out[0] = x; if (i == n - 1) out[0] = y; (n = 1: one iteration, y wins)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_first_then_last_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == 0) out[0] = std::sin(a[i]);
    if (i == n - 1) out[0] = a[i] * a[i];
  }
}
