// adversary: count-down loop: iteration 0 runs last, so if (i == 0) wins over if (i == n - 1)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_countdown_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = n - 1; i >= 0; --i) {
    if (i == 0) out[0] = std::sin(a[i]);
    if (i == n - 1) out[0] = a[i] * a[i];
  }
}
