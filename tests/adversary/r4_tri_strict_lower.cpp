// adversary: j < i (empty row 0) stores into the triangle
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_strict_lower(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      e[i * n + j] = a[i] * a[j] - a[i - j];
}
