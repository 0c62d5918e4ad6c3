// adversary: conditional second store reading the first value; condition on output
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a02_cond_restore(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * b[i];
    if (u[i] > 0) u[i] = u[i] * u[i] + b[i];
  }
}
