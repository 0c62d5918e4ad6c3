// adversary: for (i = 2; ...) if (i == 2); and if (i == 1) that never fires
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_lower_bound_2(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 2; i < n; ++i) {
    if (i == 2) out[0] = a[i] * a[i - 2];
    if (i == 1) out[1] = a[i];
  }
}
