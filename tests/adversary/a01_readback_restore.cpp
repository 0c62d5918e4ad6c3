// adversary: store, read back, store again (unconditional) in one iteration
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a01_readback_restore(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                       DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) {
    u[i] = a[i] * a[i];
    u[i] = u[i] * b[i] + u[i];
  }
}
