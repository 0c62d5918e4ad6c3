#include "dpgen/annotate.hpp"
DPGEN_KERNEL void readback_square(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * b[i];
    out[i] = out[i] * out[i] + out[i];
    if (a[i] > 0)
      out[i] = out[i] * a[i];
  }
}
