// r3: double** with a negative row coefficient and stride: u[ny - 1 - j][i] appears as the row of a count-down loop j
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_rowstride(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = ny - 1; j >= 0; --j)
    for (int i = 0; i < nx; ++i) o[j][i] = u[j][i] * u[j][nx - 1 - i];
}
