// adversary: k in [i, j] for j >= i
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_two_outer_bounds(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      double s = 0;
      for (int k = i; k <= j; ++k) s += a[k];
      e[i * n + j] = s * s;
    }
}
