// A hydro code's advection kernel shape (issue 20, defect 4): the sweep
// direction picks the nest, `if (dir == X_DIR) ... else if (dir == Y_DIR)`
// with the directions as macros, then a second pair of plain ifs on the same
// flag. Flat 2D arrays, an index macro.
#include "dpgen/annotate.hpp"

#define X_DIR 1
#define Y_DIR 2
#define IDX(i, j) ((i) + (j) * nx)

DPGEN_KERNEL void advect_dir_branches(DPGEN_IN const double* q, DPGEN_OUT double* dq,
                                      DPGEN_OUT double* mass, int nx, int ny, int dir) {
  if (dir == X_DIR) {
    for (int j = 0; j < ny; ++j)
      for (int i = 1; i < nx; ++i)
        dq[IDX(i, j)] = q[IDX(i, j)] * q[IDX(i, j)] - q[IDX(i - 1, j)];
  } else if (dir == Y_DIR) {
    for (int j = 1; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        dq[IDX(i, j)] = q[IDX(i, j)] - q[IDX(i, j - 1)] * q[IDX(i, j)];
  }
  if (dir == X_DIR)
    for (int j = 0; j < ny; ++j)
      mass[j] = q[IDX(0, j)];
  if (dir == Y_DIR)
    for (int j = 0; j < ny; ++j)
      mass[j] = 2.0 * q[IDX(nx - 1, j)];
}
