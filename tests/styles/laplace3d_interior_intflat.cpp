// 3D 7-point Laplacian on the interior only (boundary cells untouched), with
// an int flat index and int strides, as most mini-apps write it.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void laplace3d_interior_intflat(DPGEN_IN const double* p, DPGEN_OUT double* lap,
                                             int nx, int ny, int nz, double inv_h2) {
  const int nxy = nx * ny;
  for (int z = 1; z < nz - 1; ++z)
    for (int y = 1; y < ny - 1; ++y)
      for (int x = 1; x < nx - 1; ++x) {
        int c = x + y * nx + z * nxy;
        lap[c] = inv_h2 * (p[c - 1] + p[c + 1] + p[c - nx] + p[c + nx] + p[c - nxy] + p[c + nxy] -
                           6.0 * p[c]);
      }
}
