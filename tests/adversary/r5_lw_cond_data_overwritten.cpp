// adversary: if (a[j] > 0) K[j + 1] = g; K[j] = f; (the overwritten store conditional)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_cond_data_overwritten(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    if (a[j] > 0.0) K[j + 1] = b[j] * b[j];
    K[j] = a[j] * b[j];
  }
}
