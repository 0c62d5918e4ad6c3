// adversary: accumulator reset under an index condition inside the loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_reset_in_if(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int j = 0; j < n; ++j) {
    if (j % 2 == 0) s = 0.0;
    s += a[j] * a[j];
    u[j] = s;
  }
}
