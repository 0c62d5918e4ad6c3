// adversary: K[j] = f; K[j + s] = g; with s a parameter (0, 1, 2)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_param_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n, int s) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + s] = std::sin(a[j]);
  }
}
