// adversary: the loop's pair, then K[0] = h after the loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_then_statement(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j] = a[j] * a[j];
    K[j + 1] = 2.0 * a[j];
  }
  K[0] = 0.5;
}
