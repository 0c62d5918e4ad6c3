// adversary: K[j + 1] = g; K[j] += f; (K[j] = g(j - 1) + f(j))
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_next_then_pluseq(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = std::sin(a[j]);
    K[j] += a[j] * a[j];
  }
}
