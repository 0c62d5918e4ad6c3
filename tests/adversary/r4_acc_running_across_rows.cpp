// adversary: accumulator declared outside the outer loop, not reset per row (a running sum across rows)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_running_across_rows(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  double s = 0;
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}
