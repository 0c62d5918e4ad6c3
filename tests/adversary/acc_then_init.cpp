#include "dpgen/annotate.hpp"
DPGEN_KERNEL void acc_then_init(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  for (int i = 0; i < n; ++i)
    out[i] += a[i] * a[i];
  for (int i = 0; i < m; ++i)
    out[2 * i] = a[i];
}
