#include "dpgen/annotate.hpp"
DPGEN_KERNEL void after_loop_readback(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i] * a[i];
  out[0] = out[0] * 2.0 + a[0];
}
