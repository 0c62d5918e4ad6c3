// adversary: row 0 read at i-1, i+1; stored to row m-1
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_const_row_neighbours(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 1; i + 1 < n; ++i) b[m - 1][i] = a[0][i + 1] * a[0][i - 1] - a[m - 1][i];
}
