#include "dpgen/annotate.hpp"
DPGEN_KERNEL void nest_shift_acc(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    y[j] = 0;
    for (int i = 0; i < n; ++i)
      y[j + 1] += A[j * n + i] * x[i];
  }
}
