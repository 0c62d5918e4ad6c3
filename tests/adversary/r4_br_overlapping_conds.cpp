// adversary: if (flag > 0) nest; if (flag > 1) nest overwrites (not exclusive)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_overlapping_conds(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  for (int i = 0; i < n; ++i) u[i] = a[i];
  if (flag > 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag > 1)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i] * a[i];
}
