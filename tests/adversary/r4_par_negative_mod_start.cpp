// adversary: start 1 + (j - 1) % 2: C++ % is -1 at j = 0, so the start is 0, 1, 2, 1, 2, ...
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_negative_mod_start(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 1 + (j - 1) % 2; i < n; i += 2)
      e[j * n + i] = a[j * n + i] * a[j * n + i] + 1.0;
}
