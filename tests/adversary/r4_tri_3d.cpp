// adversary: tetrahedral nest k, j<=k, i<=j
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_3d(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int k = 0; k < n; ++k)
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= j; ++i)
        e[(k * n + j) * n + i] = a[i] * a[j] * a[k];
}
