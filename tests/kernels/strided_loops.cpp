// Loops that step by a constant: full weighting restriction to a coarse grid
// (the fine index steps by 2, the coarse one by 1: i / 2 is exact), and a
// red or black half of a 2D grid by rows (the colour fixes the first cell).
#include "test_kernels.hpp"

DPGEN_KERNEL void restrict_full_weighting(DPGEN_IN const double* fine, DPGEN_OUT double* coarse,
                                          int nf) {
  for (int i = 2; i < nf - 1; i += 2)
    coarse[i / 2] = 0.25 * fine[i - 1] + 0.5 * fine[i] + 0.25 * fine[i + 1];
}

DPGEN_KERNEL void every_third(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int first) {
  for (int i = first; i < n; i += 3)
    v[i] = u[i] * u[i] - (i >= 1 ? u[i - 1] : 0.0);
}
