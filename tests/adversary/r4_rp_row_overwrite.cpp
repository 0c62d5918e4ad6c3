// adversary: all rows written, then row m-1 overwritten
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_row_overwrite(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int i = 0; i < n; ++i) b[m - 1][i] = a[0][i] * 3.0;
}
