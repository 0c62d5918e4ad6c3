// Arrays updated in place (DPGEN_INOUT), element by element: an explicit
// reaction step on the interior only (the end cells pass through), with a
// conditional second update of the same element, and a relaxation of a
// state toward a target.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void react_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* rate, int n,
                                double dt) {
  for (int i = 1; i < n - 1; ++i) {
    u[i] += dt * rate[i] * u[i] * (1.0 - u[i]);
    if (u[i] > 0.5)
      u[i] = 0.5 + 0.5 * std::tanh(u[i] - 0.5);
  }
}

DPGEN_KERNEL void relax_inplace(DPGEN_INOUT double* u, DPGEN_IN const double* target, int n,
                                double w) {
  int i;
  for (i = 0; i < n; i++)
    u[i] = (1.0 - w) * u[i] + w * target[i] * target[i];
}
