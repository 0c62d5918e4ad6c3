#include "dpgen/annotate.hpp"
DPGEN_KERNEL void matvec(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_OUT double* y, int n, int m) {
  for (int j = 0; j < n; ++j) {
    y[j] = 0;
    for (int i = 0; i < m; ++i)
      y[j] += A[j * m + i] * x[i] * x[i];
  }
}
