// adversary: else-if chain of 3 on a parameter inside the accumulating loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_param_branch_in_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  double s = 0.5;
  for (int i = 0; i < n; ++i) {
    if (flag == 0) s += a[i];
    else if (flag == 1) s += a[i] * a[i];
    else s -= a[i] * a[i] * a[i];
  }
  out[0] = s * s;
}
