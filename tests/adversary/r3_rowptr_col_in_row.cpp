// r3: double** where the row index is the column counter (transpose read): o[j][i] = u[i][j]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_rowptr_col_in_row(DPGEN_IN double** u, DPGEN_OUT double** o, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) o[j][i] = u[i][j] * u[j][i];
}
