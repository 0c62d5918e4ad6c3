// adversary: per-row max over a triangular row, started from the diagonal
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_per_row_triangular(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int j = 0; j < n; ++j) {
    double m = a[j * n + j];
    for (int i = 0; i < j; ++i) m = fmax(m, a[j * n + i]);
    r[j] = m * m;
  }
}
