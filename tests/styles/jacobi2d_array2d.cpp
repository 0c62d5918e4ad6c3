// Jacobi sweep on a grid with a compile-time row length, C-style 2D array
// parameters `double a[][JN]`.
#include "dpgen/annotate.hpp"

#define JN 8

DPGEN_KERNEL void jacobi2d_array2d(DPGEN_IN const double a[][JN], DPGEN_IN const double f[][JN],
                                   DPGEN_OUT double b[][JN], int ny, double h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < JN - 1; ++i)
      b[j][i] = 0.25 * (a[j - 1][i] + a[j + 1][i] + a[j][i - 1] + a[j][i + 1] - h2 * f[j][i]);
}
