#include "dpgen/annotate.hpp"
DPGEN_KERNEL void cond_readback_else(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * a[i];
    if (a[i] > 0)
      out[i] = out[i] * 2.0;
    else
      out[i] = out[i] * 3.0;
  }
}
