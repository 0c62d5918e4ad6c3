// adversary: s -= ... with a nonzero init
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_minus_eq(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                  DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s -= a[i] * b[i];
  out[0] = s * s;
}
