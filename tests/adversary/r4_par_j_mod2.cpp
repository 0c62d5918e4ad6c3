// adversary: start j % 2, step 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_j_mod2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = j % 2; i < n; i += 2)
      e[j * n + i] = a[j * n + i] * a[j * n + i] + a[i];
}
