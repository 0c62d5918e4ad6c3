// adversary: K[j + 1] = a[j]; K[j] = K[j] + b[j]; (reads what the previous iteration stored)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_reads_prev_iter(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* K, int n) {
  K[0] = 1.0;
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    K[j] = K[j] * b[j];
  }
}
