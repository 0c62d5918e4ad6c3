// adversary: if (n < 2) return; for (j = 0; j < n - 1; j++) { K[j] = ..; K[j + 1] = ..; }
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_guard_shorter_loop(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  if (n < 2) return;
  for (int j = 0; j < n - 1; j++) {
    K[j] = a[j] * a[j + 1];
    K[j + 1] = a[j + 1] - a[j];
  }
}
