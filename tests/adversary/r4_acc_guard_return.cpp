// adversary: guard return before the accumulator
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_guard_return(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  out[0] = 0.0;
  if (n < 3) return;
  double s = 0;
  for (int i = 1; i < n - 1; ++i) s += a[i] * (a[i + 1] - a[i - 1]);
  out[0] = s * s;
}
