// adversary: if (i == 0) rowfirst[j] = ... in a 2D nest (one per row)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_row_first(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* rowfirst, int nx, int ny) {
  int i, j;
  for (j = 0; j < ny; j++)
    for (i = 0; i < nx; i++) {
      b[j * nx + i] = a[j * nx + i] * a[j * nx + i];
      if (i == 0) rowfirst[j] = 2.0 * a[j * nx + i] + a[j * nx + nx - 1];
    }
}
