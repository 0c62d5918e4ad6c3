// adversary: CRASH (hang): a local named dpgen_<x>; the renaming loop keeps the reserved prefix forever
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_min_local_dpgen_prefix_hang(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    const double dpgen_x = u[i] * u[i];
    out[i] = dpgen_x + u[i];
  }
}
