// adversary: per-row max of the old row, then the row divided in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_rowmax_per_row(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    double m = 0.5;
    for (int i = 0; i < nx; ++i) m = std::max(m, std::fabs(u[IDX(i, j)]));
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] / m;
  }
}
