#include "dpgen/annotate.hpp"
DPGEN_KERNEL void mid_store(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i)
    u[i] = a[i];
  u[n / 2] = a[0] * a[n - 1];
  u[1] = 7.0 * a[1] * a[1];
}
