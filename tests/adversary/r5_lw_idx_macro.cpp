// adversary: IDX macro shift: K[IDX(j) - 1] = f; K[IDX(j)] = g;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(j) ((j) + 1)

DPGEN_KERNEL void r5_lw_idx_macro(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  int j;
  for (j = 0; j < n; j++) {
    K[IDX(j) - 1] = a[j] * a[j];
    K[IDX(j)] = std::cos(a[j]);
  }
}
