#include "dpgen/annotate.hpp"
DPGEN_KERNEL void prefix_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  out[0] = a[0];
  for (int i = 1; i < n; ++i)
    out[i] = out[i - 1] + a[i];
}
