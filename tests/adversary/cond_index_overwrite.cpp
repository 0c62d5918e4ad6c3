#include "dpgen/annotate.hpp"
DPGEN_KERNEL void cond_index_overwrite(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i];
    if (i == n - 1)
      out[i] = out[i] * b[i];
  }
}
