// r3 minimal: double** read at a mirrored row u[ny - 1 - j][i]: the adjoint indexes u_adj[-c_j][c_i] with c_i ~ 2^40 * ny (segfault)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_min_rowptr_rev_row(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[j][i] = u[ny - 1 - j][i];
}
