#include "dpgen/annotate.hpp"
DPGEN_KERNEL void nest_readback_same(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i] * a[i];
  for (int i = 0; i < n; ++i)
    out[i] = out[i] * b[i];
}
