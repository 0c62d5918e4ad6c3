// adversary: K[2 * j] = f; K[2 * j + 3] = g; (never the same element)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_coef2_odd_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[2 * j + 3] = std::sin(a[j]);
    K[2 * j] = a[j] * a[j];
  }
}
