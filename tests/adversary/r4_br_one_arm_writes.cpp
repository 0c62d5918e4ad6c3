// adversary: only one arm writes the second output
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_one_arm_writes(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                       DPGEN_OUT double* v, int n, int flag) {
  for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag == 0) {
    for (int i = 0; i < n; ++i) v[i] = a[i] * u[i];
  }
}
