// adversary: float 3D 7-point stencil, int flat index local
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a28_3d_float(DPGEN_IN const float* u, DPGEN_OUT float* o, int nx, int ny, int nz) {
  for (int z = 1; z < nz - 1; ++z)
    for (int y = 1; y < ny - 1; ++y)
      for (int x = 1; x < nx - 1; ++x) {
        const int c = (z * ny + y) * nx + x;
        o[c] = u[c] * (u[c - 1] + u[c + 1] + u[c - nx] + u[c + nx] + u[c - nx * ny] + u[c + nx * ny] - 6.0f * u[c]);
      }
}
