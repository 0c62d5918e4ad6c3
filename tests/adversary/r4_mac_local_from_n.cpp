// adversary: kernel-level local int h = n / 2 used in macro and bounds
#include "dpgen/annotate.hpp"
#define MIR(i) (h - 1 - (i))

DPGEN_KERNEL void r4_mac_local_from_n(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  const int h = n / 2;
  for (int i = 0; i < h; ++i) u[i] = a[MIR(i)] * a[i + h];
}
