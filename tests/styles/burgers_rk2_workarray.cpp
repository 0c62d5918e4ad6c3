// Two-stage (Heun) step of inviscid Burgers with central differences: the
// first nest writes the predictor into a work array, the second reads it.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void burgers_rk2_workarray(DPGEN_IN const double* u, DPGEN_OUT double* work,
                                        DPGEN_OUT double* u_next, int n, double c) {
  for (int i = 1; i < n - 1; ++i)
    work[i] = u[i] - c * u[i] * (u[i + 1] - u[i - 1]);
  for (int i = 2; i < n - 2; ++i)
    u_next[i] = 0.5 * (u[i] + work[i] - c * work[i] * (work[i + 1] - work[i - 1]));
}
