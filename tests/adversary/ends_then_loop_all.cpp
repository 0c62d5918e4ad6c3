#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ends_then_loop_all(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  u[0] = a[0] * a[0];
  u[n - 1] = 2.0 * a[n - 1];
  for (int i = 0; i < n; ++i)
    if (i > 0 && i < n - 1)
      u[i] = a[i] * 5.0;
}
