// adversary: two accumulators named s in separate blocks, both read after their loops
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_same_name_two_blocks(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  {
    double s = 0;
    for (int i = 0; i < n; ++i) s += a[i] * a[i];
    out[0] = s;
  }
  {
    double s = 1;
    for (int i = 0; i < n; ++i) s += a[i];
    out[1] = s * s;
  }
}
