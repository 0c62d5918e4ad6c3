// adversary: accumulator over a parity loop, start j % 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_accum_step2(DPGEN_IN const double* a, DPGEN_OUT double* r, int n, int m) {
  for (int j = 0; j < m; ++j) {
    double s = 0;
    for (int i = j % 2; i < n; i += 2) s += a[j * n + i] * a[j * n + i];
    r[j] = s;
  }
}
