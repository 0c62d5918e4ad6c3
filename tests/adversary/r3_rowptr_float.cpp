// r3: float** row pointers, 5-point interior stencil, long sizes
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_float(DPGEN_IN float** u, DPGEN_OUT float** o, long nx, long ny) {
  for (long j = 1; j < ny - 1; ++j)
    for (long i = 1; i < nx - 1; ++i)
      o[j][i] = u[j][i] * (u[j][i - 1] + u[j][i + 1] - u[j - 1][i] * u[j + 1][i]);
}
