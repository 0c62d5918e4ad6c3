// adversary: banded stores e[i][j] for |i-j|<=1 via min/max
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_window_store(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j)
      e[i * n + j] = a[i] * a[j] + (i - j);
}
