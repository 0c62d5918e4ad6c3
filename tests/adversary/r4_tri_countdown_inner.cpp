// adversary: inner loop j = i down to 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_countdown_inner(DPGEN_IN const double* L, DPGEN_IN const double* x,
                                         DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j >= 0; --j) s += L[i * n + j] * x[j] * x[j];
    y[i] = s;
  }
}
