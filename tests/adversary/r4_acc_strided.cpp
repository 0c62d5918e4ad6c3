// adversary: accumulator over a step-2 loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_strided(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 1; i < n; i += 2) s += a[i] * a[i - 1];
  out[0] = s * s;
}
