#include "dpgen/annotate.hpp"
DPGEN_KERNEL void temp_ifelse_same(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double t = a[i];
    if (b[i] > 0)
      t = t * b[i];
    out[i] = t;
  }
}
