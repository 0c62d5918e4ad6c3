#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ifelse_same_read(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    if (b[i] > 0)
      out[i] = a[i] * 2.0;
    else
      out[i] = a[i] * 3.0;
  }
}
