// adversary: accumulating loop with continue
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_continue(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    if (i % 3 == 1) continue;
    s += a[i] * a[i];
  }
  out[0] = s * s;
}
