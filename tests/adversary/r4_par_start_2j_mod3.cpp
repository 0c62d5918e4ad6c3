// adversary: start (2 * j) % 3, step 3
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_start_2j_mod3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = (2 * j) % 3; i < n; i += 3)
      e[j * n + i] = a[j * n + i] * a[j * n + i] * (j + 1);
}
