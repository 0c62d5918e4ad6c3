// adversary: C89 column max into an output row through an IDX macro, loops i outer j inner
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_mm_colmax_c89_idx(DPGEN_IN const double* a, DPGEN_OUT double* cmax, int nx, int ny) {
  int i, j;
  for (i = 0; i < nx; i++) {
    cmax[i] = a[IDX(i, 0)];
    for (j = 1; j < ny; j++)
      cmax[i] = cmax[i] > a[IDX(i, j)] ? cmax[i] : a[IDX(i, j)];
  }
}
