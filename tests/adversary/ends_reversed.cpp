#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ends_reversed(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  u[n - 1] = a[n - 1] * a[0];
  u[0] = 3.0 * a[0] * a[n - 1];
  for (int i = 1; i < n - 1; ++i)
    u[i] = a[i] * a[i];
}
