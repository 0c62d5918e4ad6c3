// Pressure gradient on a MAC (staggered) grid: p at cell centres (ny x nx),
// gx on x faces (ny x (nx+1)), gy on y faces ((ny+1) x nx); interior faces
// only, one loop nest per component, `double**` row pointers.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void grad_staggered_rowptr(DPGEN_IN double** p, DPGEN_OUT double** gx,
                                        DPGEN_OUT double** gy, int nx, int ny, double inv_h) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i)
      gx[j][i] = (p[j][i] - p[j][i - 1]) * inv_h;
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      gy[j][i] = (p[j][i] - p[j - 1][i]) * inv_h;
}
