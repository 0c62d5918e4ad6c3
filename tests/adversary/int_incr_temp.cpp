#include "dpgen/annotate.hpp"
DPGEN_KERNEL void int_incr_temp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n - 1; ++i) {
    int k = i;
    k += 1;
    out[i] = a[k] * a[i];
  }
}
