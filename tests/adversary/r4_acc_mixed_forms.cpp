// adversary: s = s + x in one arm, s += y in the other
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_mixed_forms(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) s = s + a[i] * a[i];
    else s += 2.0 * a[i];
  }
  out[0] = s * s;
}
