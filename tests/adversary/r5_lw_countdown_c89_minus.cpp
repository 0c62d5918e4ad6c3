// adversary: C89 count-down with a negative shift: K[j] = f; K[j - 1] = g;
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_countdown_c89_minus(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  int j;
  for (j = n; j >= 1; j--) {
    K[j] = a[j] * a[j];
    K[j - 1] = 2.0 * a[j] + a[j - 1];
  }
}
