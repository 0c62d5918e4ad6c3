// adversary: start j + j % 2 (moving by 1 or 2 per row), step 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_start_mod2_plus_j(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = j + j % 2; i < n; i += 2)
      e[j * n + i] = a[i] * a[j] * a[i];
}
