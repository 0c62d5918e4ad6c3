// adversary: u[k] before the loop, loop overwrites interior; k coincides
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a08_straight_k_before(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int k) {
  u[k] = 5.0 * a[0] * a[0];
  for (int i = 1; i < n - 1; ++i) u[i] = a[i] - a[i - 1];
  u[n - 1] = a[k] * a[n - 1];
}
