#include "dpgen/annotate.hpp"
DPGEN_KERNEL void cond_nested(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] + b[i];
    if (a[i] > 0) {
      out[i] = 2.0 * out[i];
      if (b[i] > 0)
        out[i] = out[i] * b[i];
    } else {
      out[i] = out[i] - 1.0;
    }
  }
}
