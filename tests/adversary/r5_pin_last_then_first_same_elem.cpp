// adversary: if (i == n - 1) out[0] = y; if (i == 0) out[0] = x; (n = 1: x wins, else y)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_last_then_first_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) out[0] = a[i] * a[i];
    if (i == 0) out[0] = std::sin(a[i]);
  }
}
