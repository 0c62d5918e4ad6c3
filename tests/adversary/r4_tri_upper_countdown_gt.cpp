// adversary: for (j = n - 1; j > i; --j) stores
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_upper_countdown_gt(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j > i; --j)
      e[i * n + j] = a[i] - a[j] * a[j - i];
}
