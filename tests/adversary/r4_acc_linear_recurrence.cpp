// adversary: s = 0.5 * s + a[i]
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_linear_recurrence(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s = 0.5 * s + a[i] * a[i];
  out[0] = s;
}
