// adversary: int d = dir; if (d == 1) nest; d = 2; if (d == 2) nest (overwrite, no readback)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_br_local_changes_between_w(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int flag) {
  int d = flag;
  if (d == 1)
    for (int i = 0; i < n; ++i) u[i] = a[i] * a[i];
  d = 2;
  if (d == 2)
    for (int i = 0; i < n; ++i) u[i] = 3.0 * a[i];
}
