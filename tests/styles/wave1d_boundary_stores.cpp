// Leapfrog step of the 1D wave equation: a leading guard, a fixed end and an
// open end stored outside the loop, then the interior.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void wave1d_boundary_stores(DPGEN_IN const double* u, DPGEN_IN const double* u_prev,
                                         DPGEN_OUT double* u_next, int n, double c2) {
  if (n < 3)
    return;
  u_next[0] = 0.0;
  u_next[n - 1] = u[n - 2];
  for (int i = 1; i < n - 1; ++i)
    u_next[i] = 2.0 * u[i] - u_prev[i] + c2 * (u[i + 1] - 2.0 * u[i] + u[i - 1]);
}
