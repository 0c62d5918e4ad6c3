// adversary: multiplicative accumulator s *= a[i]
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_product(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 1.0;
  for (int i = 0; i < n; ++i) s *= a[i];
  out[0] = s;
}
