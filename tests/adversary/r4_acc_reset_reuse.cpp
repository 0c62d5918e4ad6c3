// adversary: accumulator, used, reset, reused by a second loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_reset_reuse(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                     DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double first = s;
  s = 0.0;
  for (int i = 0; i < n; ++i) s += b[i] * a[i];
  out[0] = first * s;
  out[1] = s + first * first;
}
