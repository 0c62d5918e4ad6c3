// adversary: double** with a std::min triangular interior and constant row 0
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_rp_ghost_rows_triangle_min(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  for (int i = 0; i < n; ++i) b[0][i] = a[m - 1][i] * a[0][i];
  for (int j = 1; j < m; ++j)
    for (int i = 0; i < std::min(n, j); ++i) b[j][i] = a[j][i] * a[j - 1][i];
}
