// adversary: for (i = n - 1 - j % 2; i >= 0; i -= 2)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_countdown_step2(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = n - 1 - j % 2; i >= 0; i -= 2)
      e[j * n + i] = a[j * n + i] * a[i];
}
