// adversary: if (i == n - 1 - j) anti[j] = ... (one per j)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_antidiag_elem(DPGEN_IN const double* a, DPGEN_OUT double* anti, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == n - 1 - j) anti[j] = a[j * n + i] * a[j * n + i];
}
