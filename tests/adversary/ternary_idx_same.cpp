#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ternary_idx_same(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = i > 0 ? a[i] + a[i - 1] : a[i];
}
