// adversary: for j { out[j]=0; for i out[j+1] += } must be rejected
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a06_outer_shift_accum(DPGEN_IN const double* a, DPGEN_OUT double* o, int n, int m) {
  for (int j = 0; j < n; ++j) {
    o[j] = 0;
    for (int i = 0; i < m; ++i) o[j + 1] += a[j * m + i];
  }
}
