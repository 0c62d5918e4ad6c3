// adversary: if (flag == 0) nest; if (flag == 0) nest: not exclusive, both write u
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_same_cond_twice(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  if (flag == 0)
    for (int i = 0; i < n; ++i) u[i] = a[i] * 3.0;
}
