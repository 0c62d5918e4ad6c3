// r3: double** with the row index from the inner counter and a diagonal: o[j][i] = u[i][i] * u[j][i] (nx == ny)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_diag(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[j][i] = u[i][i] * u[j][i];
}
