#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ternary_data_same(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = b[i] > 0 ? a[i] * b[i] : a[i];
}
