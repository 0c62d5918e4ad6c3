// adversary: rows of length nx + 1: K[j*(nx+1) + i] = f; K[j*(nx+1) + i + 1] = g; (meet within a row only)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_rowwise_2d(DPGEN_IN const double* a, DPGEN_OUT double* K, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      K[j * (nx + 1) + i] = a[j * nx + i] * a[j * nx + i];
      K[j * (nx + 1) + i + 1] = std::sin(a[j * nx + i]);
    }
}
