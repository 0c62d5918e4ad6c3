// adversary: if (i == 0 && j == 0) and if (j == ny - 1 && i == nx - 1) in a 2D nest
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_2d_corner_and(DPGEN_IN const double* a, DPGEN_OUT double* b, DPGEN_OUT double* c, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      b[j * nx + i] = 2.0 * a[j * nx + i];
      if (i == 0 && j == 0) c[0] = a[0] * a[0];
      if (j == ny - 1 && i == nx - 1) c[1] = std::sin(a[j * nx + i]);
    }
}
