// adversary: if (flag == 0) { nest; return; } second nest
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_arm_return(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    return;
  }
  for (int i = 0; i < n; ++i) u[i] = a[i] + 1.0;
}
