// r3: double** flux accumulation along rows o[j][i] += f; o[j][i + 1] -= f
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_rowptr_accum(DPGEN_IN double** u, DPGEN_OUT double** o, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx - 1; ++i) {
      double f = u[j][i] * u[j][i + 1];
      o[j][i] += f;
      o[j][i + 1] -= f;
    }
}
