// adversary: flag = 1 - flag before two exclusive ifs
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_param_assigned_before(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* v, int n, int flag) {
  flag = 1 - flag;
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  else
    for (int i = 0; i < n; ++i) u[i] = 2.0 * a[i];
  for (int i = 0; i < n; ++i) v[i] = flag * a[i] * a[i];
}
