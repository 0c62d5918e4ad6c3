#include "dpgen/annotate.hpp"
DPGEN_KERNEL void c89_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  int i;
  for (i = 0; i < n - 1; i++)
    out[i] = a[i] * a[i + 1];
  out[i] = a[i] * 3.0;
}
