// adversary: accumulator in a triangular loop (cumulative sums)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_triangular(DPGEN_IN const double* a, DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i; ++j) s += a[j] * a[i - j];
    y[i] = s * s;
  }
}
