// Smallest kernel found that gets a wrong adjoint (issue 9, defect 1): two
// loops over the same input with the same counter name and different lower
// bounds. The adjoint gives cell 0 of `a` the seed of y[0], a cell the
// forward never writes.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void two_loops_minimal(DPGEN_IN const double* a, DPGEN_OUT double* x,
                                    DPGEN_OUT double* y, int n) {
  for (int i = 0; i < n; ++i)
    x[i] = a[i];
  for (int i = 1; i < n; ++i)
    y[i] = a[i];
}
