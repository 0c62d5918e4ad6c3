// Upwind advection with unsigned size and counter, max/min split of the
// velocity, i++.
#include "dpgen/annotate.hpp"

#include <algorithm>

DPGEN_KERNEL void upwind_unsigned(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                  DPGEN_OUT double* q_new, unsigned n, double dt_dx) {
  for (unsigned i = 1; i < n - 1; i++) {
    double a = u[i];
    q_new[i] = q[i] - dt_dx * (std::max(a, 0.0) * (q[i] - q[i - 1]) +
                               std::min(a, 0.0) * (q[i + 1] - q[i]));
  }
}
