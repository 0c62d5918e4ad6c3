// adversary: accumulator init read by an output before the loop, read again after
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_read_before_and_after(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = a[0] * a[0];
  out[0] = s;
  for (int i = 1; i < n; ++i) s += a[i];
  out[1] = s * s;
}
