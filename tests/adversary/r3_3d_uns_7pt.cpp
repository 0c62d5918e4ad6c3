// r3: 3D 7-point interior stencil with unsigned sizes and counters
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_3d_uns_7pt(DPGEN_IN const double* u, DPGEN_OUT double* o, unsigned nx, unsigned ny, unsigned nz) {
  for (unsigned k = 1; k + 1 < nz; ++k)
    for (unsigned j = 1; j + 1 < ny; ++j)
      for (unsigned i = 1; i + 1 < nx; ++i) {
        unsigned c = (k * ny + j) * nx + i;
        o[c] = u[c] * (u[c - 1] + u[c + 1] + u[c - nx] + u[c + nx] + u[c - nx * ny] + u[c + nx * ny]);
      }
}
