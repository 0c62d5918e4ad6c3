#include "dpgen/annotate.hpp"
DPGEN_KERNEL void overwrite_next(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (i + 1 < n)
      out[i + 1] += a[i] * b[i];
    out[i] = b[i] * b[i];
  }
}
