#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ends_plus(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  u[0] = a[0] * a[0];
  u[n - 1] += a[n - 1] * 3.0;
  u[0] += a[n - 1];
}
