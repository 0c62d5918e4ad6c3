// adversary: K[j + 1] = f(j); if (j == 0) K[0] = g;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_pinned_shift_mix(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    if (j == 0) K[0] = std::exp(a[0]);
  }
}
