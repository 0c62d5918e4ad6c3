// A 3D heat step on `double***` grids as C codes allocate them: an array of
// planes, each an array of row pointers, each row its own block. C89
// counters, a separate diffusivity field.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat3d_planes_scattered(DPGEN_IN double*** u, DPGEN_IN double*** k,
                                          DPGEN_OUT double*** un, int nx, int ny, int nz,
                                          double dt) {
  int i, j, m;
  for (m = 1; m < nz - 1; m++)
    for (j = 1; j < ny - 1; j++)
      for (i = 1; i < nx - 1; i++)
        un[m][j][i] = u[m][j][i] + dt * k[m][j][i] *
                                       (u[m][j][i + 1] + u[m][j][i - 1] + u[m][j + 1][i] +
                                        u[m][j - 1][i] + u[m + 1][j][i] + u[m - 1][j][i] -
                                        6.0 * u[m][j][i]);
}
