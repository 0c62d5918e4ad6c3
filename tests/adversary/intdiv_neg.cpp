#include "dpgen/annotate.hpp"
DPGEN_KERNEL void intdiv_neg(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[(i - 1) / 2 + 1] * a[i];
}
