// adversary: b[0][i] += a[j][i] over all rows after b[0][i] = 0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_colsum_into_row0(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = 0.0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[0][i] += a[j][i] * a[j][i];
}
