#include "dpgen/annotate.hpp"
DPGEN_KERNEL void uncond_readback(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    out[i] += b[i] * out[i];
  }
}
