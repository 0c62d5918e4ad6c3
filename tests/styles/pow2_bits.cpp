// pow2_bits (tests/styles/): stores at flat indices built with bit
// operations on power-of-two grids, `b[(j << lg) | i]` with n = 1 << lg
// (issue 22). A shift by lg is a product with n, and the `|` of a multiple of
// n and a counter the loops keep below n is their sum: the index is affine.
#include "dpgen/annotate.hpp"

#include <cmath>

// n x n, the index by a shift of the row and an `|` of the column; the reads
// at the transposed element go through scatter form.
DPGEN_KERNEL void pow2_transpose_scale(DPGEN_IN const double* a, DPGEN_OUT double* b, int lg) {
  const int n = 1 << lg;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      b[(j << lg) | i] = std::sin(a[(i << lg) | j]) * a[j * n + i];
}

// The same after a guard on the shift (the local is made under it, `lg` out of
// range computes no 1 << lg): still a power of two where the stores run.
DPGEN_KERNEL void pow2_guarded(DPGEN_IN const double* a, DPGEN_OUT double* b, int lg) {
  if (lg < 0 || lg > 15)
    return;
  const int n = 1 << lg;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      b[(j << lg) | i] = a[j * n + i] * a[j * n + i];
}

// Blocks of 8 (a constant shift): the column counter stays below 8.
DPGEN_KERNEL void blocks8(DPGEN_IN const double* a, DPGEN_OUT double* b, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < 8; ++i)
      b[(j << 3) | i] = a[j * 8 + i] * a[j * 8 + (7 - i)];
}

// A cube: the plane and the row shifted in turn, ((k * n + j) * n) | i.
DPGEN_KERNEL void pow2_cube(DPGEN_IN const double* a, DPGEN_OUT double* b, int lg) {
  const int n = 1 << lg;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        b[(((k << lg) | j) << lg) | i] =
            a[(k * n + j) * n + i] * std::exp(0.1 * a[(k * n + j) * n + i]);
}
