// y = (A x)^2 row by row with the row sum in an output of the same loop: rejected
// (a work array read inside the loop that writes it), never a wrong adjoint.
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void split_matvec_square(DPGEN_IN const double* A, DPGEN_IN const double* x, DPGEN_OUT double* s, DPGEN_OUT double* y, int n) {
  for (int j = 0; j < n; ++j) {
    s[j] = 0.0;
    for (int i = 0; i < n; ++i)
      s[j] += A[j * n + i] * x[i];
    y[j] = s[j] * s[j];
  }
}
