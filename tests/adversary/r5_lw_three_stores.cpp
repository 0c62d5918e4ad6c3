// adversary: K[j] = f; K[j + 1] = g; K[j + 2] = h;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_three_stores(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = b[j] * a[j];
    K[j + 2] = std::exp(b[j]);
  }
}
