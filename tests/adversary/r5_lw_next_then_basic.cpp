// adversary: K[j + 1] = g; K[j] = f; (order reversed)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_next_then_basic(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = std::sin(a[j]) + b[j];
    K[j] = a[j] * b[j];
  }
}
