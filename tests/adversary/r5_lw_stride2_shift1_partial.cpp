// adversary: for (j = 0; j < n; j += 2) { K[j] = f; K[j + 1] = g; K[j + 2] = h; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_stride2_shift1_partial(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j] = a[j] * a[j];
    K[j + 1] = 3.0 * a[j];
    K[j + 2] = std::cos(a[j]);
  }
}
