// adversary: K[j] = f; K[j + 1] = g; if (j == n - 1) K[0] = h; (pinned store onto K[0] of iteration 0)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_pinned_overwrites_shift(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = 2.0 * a[j];
    if (j == n - 1) K[0] = std::sin(a[j]);
  }
}
