// adversary: max over a double** 2D grid
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_rowptr_rows(DPGEN_IN double** a, DPGEN_OUT double* out, int nx, int ny) {
  double m = -7.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m = fmax(m, a[j][i] - 0.5 * a[j][i] * a[j][i]);
  out[0] = m;
}
