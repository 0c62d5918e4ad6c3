// adversary: bound i + 2 on an (n+1)-wide output, no clip
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_bound_i_plus_2_noclip(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i + 2; ++j)
      e[i * (n + 1) + j] = a[j] * a[i] + a[j];
}
