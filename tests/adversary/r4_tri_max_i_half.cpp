// adversary: lower bound std::max(i, n / 2)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_max_i_half(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = std::max(i, n / 2); j < n; ++j)
      e[i * n + j] = a[i] * a[j] * a[j];
}
