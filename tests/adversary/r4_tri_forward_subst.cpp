// adversary: forward substitution: x[i] reads x[j<i] (own output)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_forward_subst(DPGEN_IN const double* L, DPGEN_IN const double* b,
                                       DPGEN_OUT double* x, int n) {
  for (int i = 0; i < n; ++i) {
    double s = b[i];
    for (int j = 0; j < i; ++j) s -= L[i * n + j] * x[j];
    x[i] = s / L[i * n + i];
  }
}
