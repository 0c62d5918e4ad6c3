// adversary: bound std::min(n, i + 2)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_bound_i_plus_2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < std::min(n, i + 2); ++j)
      e[i * n + j] = a[j] * a[j] + a[i];
}
