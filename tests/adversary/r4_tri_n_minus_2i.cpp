// adversary: bound j < n - 2 * i (negative trip counts)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_n_minus_2i(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n - 2 * i; ++j)
      e[i * n + j] = a[j + i] * a[j + 2 * i];
}
