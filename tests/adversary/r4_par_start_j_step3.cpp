// adversary: start = j, step 3
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_start_j_step3(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; i += 3)
      e[j * n + i] = a[i] * a[j] + a[i - j];
}
