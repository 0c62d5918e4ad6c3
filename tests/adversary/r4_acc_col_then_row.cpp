// adversary: sum over columns inside j, reused by i loop and a kernel-level total
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_col_then_row(DPGEN_IN const double* a, DPGEN_OUT double* u,
                                      DPGEN_OUT double* tot, int n, int m) {
  double all = 0.0;
  for (int j = 0; j < m; ++j) {
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += a[j * n + i];
    all += s;
    for (int i = 0; i < n; ++i) u[j * n + i] = s * a[j * n + i];
  }
  tot[0] = all * all;
}
