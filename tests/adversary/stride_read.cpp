#include "dpgen/annotate.hpp"
DPGEN_KERNEL void stride_read(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n; ++i)
    out[i] = a[3 * i - 1] * a[2 * i] - a[3 * i - 2];
}
