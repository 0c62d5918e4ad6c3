// adversary: s /= (1 + a[i]^2)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_compound_div_eq(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 2.0;
  for (int i = 0; i < n; ++i) s /= (1.0 + a[i] * a[i]);
  out[0] = s;
}
