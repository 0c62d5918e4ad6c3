// Write-once rules that hold for some sizes only, so the adjoint checks them
// on entry: a leading dimension given as a parameter (rows of `ld` elements,
// columns x_min..x_max), and rows of a fixed length 8 against a size `n`.
#include "test_kernels.hpp"

DPGEN_KERNEL void leading_dim(DPGEN_IN const double* a, DPGEN_OUT double* b, const int* xmin,
                              const int* xmax, int ny, int ld) {
  int x_min = *xmin, x_max = *xmax;
  int i, j;
  for (j = 0; j < ny; j++)
    for (i = x_min; i <= x_max; i++)
      b[j * ld + i] = a[j * ld + i] * a[j * ld + i] - a[j * ld + i];
}

DPGEN_KERNEL void fixed_rows(DPGEN_IN const double (*a)[8], DPGEN_OUT double b[][8], int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      b[j][i] = 3.0 * a[j][i] * a[j][i];
}
