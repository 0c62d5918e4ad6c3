// r3: double** output stored at a mirrored row o[ny - 1 - j][i]
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_rev_out(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[ny - 1 - j][i] = u[j][i] * u[j][i];
}
