// adversary: accumulator over an index macro with kernel-level locals
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) + (j) * ld)

DPGEN_KERNEL void r4_acc_macro_locals(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  const int ld = n;
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = 0; i < n; ++i) s += a[IDX(i, j)] * a[IDX(i, j)];
    r[j] = s;
  }
}
