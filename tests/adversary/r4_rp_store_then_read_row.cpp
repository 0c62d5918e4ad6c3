// adversary: b[0][i] stored, then b[1][i] reads b[0][i] (work row)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_store_then_read_row(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[0][i] * a[1][i];
  for (int i = 0; i < n; ++i) b[1][i] = b[0][i] * b[0][i] + a[m - 1][i];
}
