// adversary: accumulator updated only in one if arm on a parameter, read after the if
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_one_arm_only(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 1.0;
  if (flag == 0)
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
  out[0] = s * s;
}
