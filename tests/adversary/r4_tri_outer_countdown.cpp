// adversary: outer i counts down, inner j <= i
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_outer_countdown(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = n - 1; i >= 0; --i)
    for (int j = 0; j <= i; ++j)
      e[i * n + j] = a[i] * a[j] * a[j];
}
