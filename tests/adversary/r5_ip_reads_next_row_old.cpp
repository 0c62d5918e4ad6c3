// adversary: per row: an accumulator reads row j + 1 (not yet updated: old values), then row j updated
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_reads_next_row_old(DPGEN_INOUT double* u, int nx, int ny) {
  for (int j = 0; j < ny - 1; ++j) {
    double s = 0.0;
    for (int i = 0; i < nx; ++i) s += u[IDX(i, j + 1)];
    for (int i = 0; i < nx; ++i) u[IDX(i, j)] = u[IDX(i, j)] + 0.1 * s * s;
  }
}
