// adversary: accumulator read in a later nest and in a kernel-level local
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_later_nest_and_local(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double mean = s / n;
  for (int i = 0; i < n; ++i) u[i] = a[i] * s - mean * a[i];
}
