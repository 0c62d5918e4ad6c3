// adversary: per row: an accumulator reads row j - 1, which the previous outer iteration already updated (new values)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_reads_prev_row_new(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 1; j < ny; ++j) {
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j - 1)];
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] + 0.1 * s * s;
  }
}
