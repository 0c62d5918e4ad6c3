#include "dpgen/annotate.hpp"
DPGEN_KERNEL void cond_overwrite_idx(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    out[i] = a[i] * a[i];
    if (i == 0)
      out[i] = 2.0 * a[i];
  }
}
