#include "dpgen/annotate.hpp"
DPGEN_KERNEL void nest_two_inner_acc(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    y[j] = x[j];
    for (int i = 0; i < n; ++i)
      y[j] += A[j * n + i] * x[i];
    for (int i = 1; i < n; ++i)
      y[j] -= A[i * n + j] * x[i - 1] * x[i];
  }
}
