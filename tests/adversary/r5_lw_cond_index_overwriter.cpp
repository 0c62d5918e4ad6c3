// adversary: K[j + 1] = g; if (j > 0) K[j] = f; (a conditional overwrite, on the index)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_cond_index_overwriter(DPGEN_IN const double* a, DPGEN_OUT double* K, int n) {
  for (int j = 0; j < n; ++j) {
    K[j + 1] = a[j] * a[j];
    if (j > 0) K[j] = std::sin(a[j]);
  }
}
