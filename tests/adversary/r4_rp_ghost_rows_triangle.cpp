// adversary: double** with a triangular interior and constant ghost rows
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_ghost_rows_triangle(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[m - 1][i] * a[0][i];
  for (int j = 1; j < m; ++j)
    for (int i = 0; i < n && i < j; ++i) b[j][i] = a[j][i] * a[j - 1][i];
}
