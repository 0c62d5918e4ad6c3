// adversary: K[j] = f; K[j - 1] = g; for j = 1..n-1
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_minus_shift(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 1; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j - 1] = b[j] * a[j - 1];
  }
}
