// r3: DPGEN_INOUT updated at even elements only (u[2 * i], i < n / 2; odd ones pass through)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_inout_stride(DPGEN_INOUT double* u, DPGEN_IN const double* c, int n) {
  for (int i = 0; i < n / 2; ++i) u[2 * i] = c[i] * u[2 * i] * u[2 * i];
}
