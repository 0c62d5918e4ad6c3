#include "dpgen/annotate.hpp"
DPGEN_KERNEL void temp_reduce_inner(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    double s = 0;
    for (int i = 0; i < n; ++i)
      s += A[j * n + i] * x[i];
    y[j] = s * s;
  }
}
