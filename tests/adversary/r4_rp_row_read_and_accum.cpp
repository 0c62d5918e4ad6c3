// adversary: row 0 of the output read back while accumulating into row 1
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_row_read_and_accum(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) { b[0][i] = a[0][i] * a[0][i]; b[1][i] = 0.0; }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) b[1][i] += b[0][i] * a[j][i];
}
