#include "dpgen/annotate.hpp"
DPGEN_KERNEL void store_then_plus_prev(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    if (i > 0)
      out[i - 1] += a[i] * b[i];
  }
}
