#include "dpgen/annotate.hpp"
DPGEN_KERNEL void cond_overwrite(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    if (b[i] > 0)
      out[i] = b[i];
  }
}
