// adversary: t = f(s); second loop accumulates into s with t
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_sum_then_weighted(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                           DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i];
  const double t = s * s;
  for (int i = 0; i < n; ++i) s += t * b[i];
  out[0] = s;
}
