// r3: double** with the row index a sum of both counters: o[j][i] = u[i + j][0] * u[j][i] (u has nx + ny rows of nx)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_antidiag(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[j][i] = u[i + j][0] * u[j][i] + u[i + j][0];
}
