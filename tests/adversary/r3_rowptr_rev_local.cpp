// r3: double** mirrored row through an int local jm = ny - 1 - j, interior rows only
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_rev_local(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i) {
      const int jm = ny - 1 - j;
      o[j][i] = u[jm][i] * u[j][i] + u[jm + 1][i];
    }
}
