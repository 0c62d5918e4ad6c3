// r3: 2D flat, unsigned sizes, rows mirrored and columns mirrored
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_2d_uns_rev(DPGEN_IN const double* u, DPGEN_OUT double* o, unsigned nx, unsigned ny) {
  for (unsigned j = 0; j < ny; ++j)
    for (unsigned i = 0; i < nx; ++i)
      o[j * nx + i] = u[(ny - 1 - j) * nx + i] * u[j * nx + (nx - 1 - i)];
}
