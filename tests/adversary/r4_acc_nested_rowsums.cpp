// adversary: sum of squared row sums (nested accumulators)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_nested_rowsums(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int m) {
  double tot = 0.0;
  for (int j = 0; j < m; ++j) {
    double r = 0.0;
    for (int i = 0; i < n; ++i) r += a[j * n + i];
    tot += r * r;
  }
  out[0] = tot * tot;
}
