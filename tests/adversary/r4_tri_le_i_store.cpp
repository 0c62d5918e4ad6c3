// adversary: j <= i stores, diagonal included
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_le_i_store(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] * a[i - j];
}
