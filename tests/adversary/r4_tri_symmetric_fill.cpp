// adversary: fills both triangles (diagonal stored twice, same value)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_symmetric_fill(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) {
      const double v = a[i] * a[j] + a[i] - a[j];
      e[i * n + j] = v;
      e[j * n + i] = v * v;
    }
}
