// adversary: y[i] += in a triangle after y[i] = 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_accum_output(DPGEN_IN const double* L, DPGEN_IN const double* x,
                                      DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    y[i] = 0.0;
    for (int j = 0; j <= i; ++j) y[i] += L[i * n + j] * x[j] * x[i];
  }
}
