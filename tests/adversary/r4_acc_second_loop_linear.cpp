// adversary: a second loop accumulates the same local (no self read)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_second_loop_linear(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                            DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * b[i];
  out[1] = s;
  for (int i = 0; i < n; ++i) s += b[i] * b[i];
  out[0] = s * s;
}
