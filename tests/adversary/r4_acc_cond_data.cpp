// adversary: conditional accumulation on data
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_cond_data(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                   DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i)
    if (a[i] > 0.1) s += a[i] * b[i];
    else s -= b[i];
  out[0] = s * s;
}
