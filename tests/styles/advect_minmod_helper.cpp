// MUSCL advection (constant positive Courant number c) with a minmod slope
// limiter written as a user helper with early returns.
#include "dpgen/annotate.hpp"

#include <cmath>

static inline double minmod(double a, double b) {
  if (a * b <= 0.0)
    return 0.0;
  return std::fabs(a) < std::fabs(b) ? a : b;
}

DPGEN_KERNEL void advect_minmod_helper(DPGEN_IN const double* q, DPGEN_OUT double* q_new, int n,
                                       double c) {
  for (int i = 2; i < n - 1; ++i) {
    double s_l = minmod(q[i - 1] - q[i - 2], q[i] - q[i - 1]);
    double s_c = minmod(q[i] - q[i - 1], q[i + 1] - q[i]);
    double f_l = q[i - 1] + 0.5 * (1.0 - c) * s_l;
    double f_r = q[i] + 0.5 * (1.0 - c) * s_c;
    q_new[i] = q[i] - c * (f_r - f_l);
  }
}
