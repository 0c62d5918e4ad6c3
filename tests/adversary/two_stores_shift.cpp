#include "dpgen/annotate.hpp"
DPGEN_KERNEL void two_stores_shift(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n - 1; ++i) {
    out[i + 1] = b[i] * a[i];
    out[i] = a[i] * a[i];
  }
}
