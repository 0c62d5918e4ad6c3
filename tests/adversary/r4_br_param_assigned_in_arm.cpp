// adversary: if (flag == 0) { nest; flag = 1; } if (flag == 1) nest: both run for flag 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_param_assigned_in_arm(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
    flag = 1;
  }
  if (flag == 1)
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
}
