// adversary: straight-line stores u[0], u[n-1], u[k] after a loop; k may coincide
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a07_straight_k(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k) {
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  u[0] = 2.0 * a[0];
  u[n - 1] = 3.0 * a[n - 1] * a[0];
  u[k] = a[k] * a[0];
}
