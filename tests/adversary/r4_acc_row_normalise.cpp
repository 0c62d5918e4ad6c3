// adversary: row sum then row store in the same outer loop
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_row_normalise(DPGEN_IN const double* a, DPGEN_OUT double* u, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 1.0;
    for (int i = 0; i < n; ++i) s += a[j * n + i] * a[j * n + i];
    for (int i = 0; i < n; ++i) u[j * n + i] = a[j * n + i] / s;
  }
}
