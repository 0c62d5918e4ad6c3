// adversary: per-row accumulator of the old row, then the row rescaled in place (one outer loop)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_rownorm_per_row(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double s = 1.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j)] * u[IDX(i, j)];
    const double inv = 1.0 / std::sqrt(s);
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] *= inv;
  }
}
