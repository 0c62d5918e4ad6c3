// adversary: bound n - i (anti-triangle), a[i+j]
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_n_minus_i(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - i; ++j)
      e[i * n + j] = a[i + j] * a[j];
}
