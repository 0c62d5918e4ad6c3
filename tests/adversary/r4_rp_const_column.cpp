// adversary: constant column a[j][0] and a[j][n-1]
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_const_column(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][0] * a[j][n - 1] + a[j][i];
}
