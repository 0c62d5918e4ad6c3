// adversary: one accumulator s accumulated in 3 else-if arms then read
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_in_elseif_arms_shared(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 1.0;
  if (flag == 0) {
    for (int i = 0; i < n; ++i) s += a[i];
  } else if (flag == 1) {
    for (int i = 0; i < n; ++i) s -= a[i] * a[i];
  } else {
    for (int i = 1; i < n; ++i) s += a[i] * a[i - 1];
  }
  out[0] = s * s;
}
