// r3: double** as planes of a 3D grid: u[k][j * nx + i], z-neighbours in other rows
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_rowptr_plane(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int k = 1; k < 3; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) o[k][j * nx + i] = u[k - 1][j * nx + i] * u[k + 1][j * nx + i] - u[k][j * nx + i];
}
