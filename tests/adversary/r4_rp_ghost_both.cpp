// adversary: ghost rows 0 and m-1 copied from rows 1 and m-2, interior squared
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_ghost_both(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int j = 1; j < m - 1; ++j)
    for (int i = 0; i < n; ++i) b[j][i] = a[j][i] * a[j][i];
  for (int i = 0; i < n; ++i) {
    b[0][i] = a[1][i] * a[0][i];
    b[m - 1][i] = a[m - 2][i] + a[m - 1][i] * a[m - 1][i];
  }
}
