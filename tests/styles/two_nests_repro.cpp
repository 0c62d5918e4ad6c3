// Issue 9, defect 1, as reported: two nests with the same counter names and
// different bounds, writing different outputs (leading dimension n+2).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void two_nests_repro(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                  DPGEN_OUT double* x, DPGEN_OUT double* y, int m, int n) {
  for (int k = 0; k < m; k++)
    for (int j = 0; j < n + 1; j++)
      x[k * (n + 2) + j] = 2.0 * a[k * (n + 2) + j];
  for (int k = 0; k < m + 1; k++)
    for (int j = 0; j < n; j++)
      y[k * (n + 2) + j] = 3.0 * b[k * (n + 2) + j];
}
