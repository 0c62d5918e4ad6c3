// adversary: int accumulator used as a later loop bound
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_int_bound(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int k = 0;
  for (int i = 0; i < n; ++i) k += 2;
  for (int i = 0; i < k / 2; ++i) u[i] = a[i] * a[i];
}
