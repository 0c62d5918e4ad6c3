// r3: double** rows mirrored u[ny - 1 - j][i] and columns mirrored u[j][nx - 1 - i]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_rowptr_rev(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) o[j][i] = u[ny - 1 - j][i] * u[j][nx - 1 - i];
}
