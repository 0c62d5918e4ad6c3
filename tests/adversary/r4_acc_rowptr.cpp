// adversary: accumulator over a constant row of a double** input
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_rowptr(DPGEN_IN double** a, DPGEN_OUT double* out, int n, int m) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[0][i] * a[m - 1][i];
  out[0] = s * s;
}
