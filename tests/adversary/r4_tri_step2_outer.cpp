// adversary: outer step 2, inner j <= i
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_step2_outer(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; i += 2)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] + a[j];
}
