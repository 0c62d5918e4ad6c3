// adversary: for j { out[j]=0; for i out[j] += } and out[j] = x then +=
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a05_outer_zero_accum(DPGEN_IN const double* a, DPGEN_OUT double* o,
                                       DPGEN_OUT double* q, int n, int m) {
  for (int j = 0; j < n; ++j) {
    o[j] = 0;
    q[j] = a[j * m] * 3.0;
    for (int i = 0; i < m; ++i) {
      o[j] += a[j * m + i] * a[j * m + i];
      q[j] -= a[j * m + i];
    }
  }
}
