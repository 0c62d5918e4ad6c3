// adversary: double** input and a flat weight input
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_mixed_flat(DPGEN_IN double** a, DPGEN_IN const double* w, DPGEN_OUT double* r,
                                   int n, int m) {
  for (int i = 0; i < n; ++i) r[i] = w[i] * a[0][i] * a[m - 1][i];
}
