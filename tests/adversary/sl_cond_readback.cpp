#include "dpgen/annotate.hpp"
DPGEN_KERNEL void sl_cond_readback(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  u[0] = a[0] * a[1];
  if (a[0] > 0)
    u[0] = u[0] * 2.0;
  for (int i = 1; i < n; ++i)
    u[i] = a[i];
}
