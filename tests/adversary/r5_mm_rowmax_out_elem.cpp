// adversary: rowmax[j] = -1e30; rowmax[j] = fmax(rowmax[j], ...) per row (an output element per row)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_rowmax_out_elem(DPGEN_IN const double* a, DPGEN_OUT double* rowmax, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    rowmax[j] = -1e3;
    for (int i = 0; i < nx; ++i) rowmax[j] = fmax(rowmax[j], a[j * nx + i] * a[j * nx + i]);
  }
}
