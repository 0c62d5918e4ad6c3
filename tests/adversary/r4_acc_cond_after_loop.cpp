// adversary: accumulator, then an if on data reading it, then accumulated again
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_cond_after_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i];
  if (s > 0) s = s * s;
  out[0] = s;
}
