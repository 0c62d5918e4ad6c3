// r3: 3D, middle loop counts down, flat int index with a mirrored j, z neighbours
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_3d_int_rev_mid(DPGEN_IN const double* u, DPGEN_OUT double* o, int nx, int ny, int nz) {
  for (int k = 1; k < nz - 1; ++k)
    for (int j = ny - 1; j >= 0; --j)
      for (int i = 0; i < nx; ++i) {
        int c = (k * ny + j) * nx + i;
        int r = (k * ny + (ny - 1 - j)) * nx + i;
        o[c] = u[r + nx * ny] * u[r - nx * ny] - u[c];
      }
}
