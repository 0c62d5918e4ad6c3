// adversary: if (i == j && j == n - 1) c[0] = ...: one iteration
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_diag_last_j(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j && j == n - 1) c[0] = a[j * n + i] * a[j * n + i];
}
