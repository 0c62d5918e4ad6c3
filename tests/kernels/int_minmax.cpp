// Integer std::min/std::max in indices (a clamped neighbour, a coarse cell),
// mixing a widened local with an int size; and a prolongation whose fine row
// is (2 * jc + dj) * nx: its write-once proof needs nx > 0, which the loops
// give.
#include "test_kernels.hpp"

#include <algorithm>

DPGEN_KERNEL void clamped_neighbour(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    const int right = std::min(i + 1, n - 1);
    const int left = std::max(i - 1, 0);
    out[i] = a[right] * a[i] - 0.5 * a[left];
  }
}

DPGEN_KERNEL void prolong_rows(DPGEN_IN const double* c, DPGEN_OUT double* f, int nx, int ncy) {
  for (int jc = 0; jc < ncy; ++jc)
    for (int dj = 0; dj < 2; ++dj)
      for (int i = 0; i < nx; ++i)
        f[(2 * jc + dj) * nx + i] = (1.0 + 0.5 * dj) * c[jc * nx + i];
}
