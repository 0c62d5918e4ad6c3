// r3: row pointers spelled const double* const* (input) and double* const* (output)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_constconst(DPGEN_IN const double* const* u, DPGEN_OUT double* const* o, int nx, int ny) {
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx - 1; ++i) o[j][i] = u[j - 1][i + 1] * u[j][i];
}
