// adversary: K[j] = f; K[j + 1] += g; (the += is overwritten by the next iteration's =)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_eq_then_pluseq(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] += 2.0 * a[j];
  }
}
