// adversary: output read before any store in the kernel (caller contents)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a34_readback_before_store(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  for (int i = 0; i < n; ++i) u[i] = u[i] * a[i];
}
