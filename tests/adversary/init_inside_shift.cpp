#include "dpgen/annotate.hpp"
DPGEN_KERNEL void init_inside_shift(DPGEN_IN const double* A, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    y[j] = A[j * n];
    for (int i = 0; i < j; ++i)
      y[i] += A[j * n + i] * A[j * n + i];
  }
}
