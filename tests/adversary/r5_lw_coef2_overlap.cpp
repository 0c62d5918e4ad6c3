// adversary: K[2 * j] = f; K[2 * j + 2] = g;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_coef2_overlap(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[2 * j + 2] = std::sin(a[j]);
    K[2 * j] = a[j] * a[j];
  }
}
