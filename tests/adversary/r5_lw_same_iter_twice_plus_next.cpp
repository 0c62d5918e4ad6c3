// adversary: K[j + 1] = g1; K[j + 1] = g2 * K[j + 1]; K[j] = f;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_same_iter_twice_plus_next(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] + 1.0;
    K[j + 1] = K[j + 1] * a[j];
    K[j] = std::exp(a[j]);
  }
}
