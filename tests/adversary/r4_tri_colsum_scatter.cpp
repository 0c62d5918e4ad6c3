// adversary: c[j] += over a triangle (scatter into the inner index)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_colsum_scatter(DPGEN_IN const double* a, DPGEN_OUT double* c, int n) {
  for (int j = 0; j < n; ++j) c[j] = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      c[j] += a[i * n + j] * a[i * n + j];
}
