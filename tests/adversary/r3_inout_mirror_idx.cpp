// r3: DPGEN_INOUT updated at a mirrored index u[n - 1 - i] (still element by element)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_inout_mirror_idx(DPGEN_INOUT double* u, DPGEN_IN const double* c, int n) {
  for (int i = 0; i < n; ++i) u[n - 1 - i] = u[n - 1 - i] * u[n - 1 - i] + c[i] * u[n - 1 - i];
}
