#include "dpgen/annotate.hpp"
DPGEN_KERNEL void nest_scale_after(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_IN const double* b, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    y[j] = b[j];
    for (int i = 0; i < n; ++i)
      y[j] += A[j * n + i] * x[i];
    y[j] = y[j] * y[j];
  }
}
