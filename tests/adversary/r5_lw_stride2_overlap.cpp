// adversary: for (j = 0; j < n; j += 2) { K[j] = f; K[j + 2] = g; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_stride2_overlap(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; j += 2) {
    K[j] = a[j] * a[j];
    K[j + 2] = std::sin(a[j]);
  }
}
