// Issue 9, defect 1, second form: the same two nests with different counter
// names in each (reported as falsely rejected), plus nonlinear bodies.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void two_nests_renamed(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                    DPGEN_OUT double* x, DPGEN_OUT double* y, int m, int n) {
  for (int k = 0; k < m; k++)
    for (int j = 0; j < n + 1; j++)
      x[k * (n + 2) + j] = 2.0 * a[k * (n + 2) + j] * a[k * (n + 2) + j];
  for (int r = 0; r < m + 1; r++)
    for (int c = 0; c < n; c++)
      y[r * (n + 2) + c] = 3.0 * b[r * (n + 2) + c] * a[c];
}
