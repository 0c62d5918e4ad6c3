#include "dpgen/annotate.hpp"
DPGEN_KERNEL void flat3d_interior(DPGEN_IN const double* u, DPGEN_IN const double* k, DPGEN_OUT double* out, int nx, int ny, int nz) {
  int sx = 1, sy = nx, sz = nx * ny;
  for (int z = 1; z < nz - 1; ++z)
    for (int y = 1; y < ny - 1; ++y)
      for (int x = 1; x < nx - 1; ++x) {
        int c = z * sz + y * sy + x * sx;
        out[c] = k[c] * (u[c + sx] + u[c - sx] + u[c + sy] + u[c - sy] + u[c + sz] + u[c - sz] - 6.0 * u[c]) + u[c] * u[c + sz];
      }
}
