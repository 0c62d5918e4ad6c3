// Face fluxes for advection with a van Leer limited reconstruction: two user
// helpers (the limiter and an upwind flux function), velocity on faces.
#include "dpgen/annotate.hpp"

static inline double vanleer(double a, double b) {
  double p = a * b;
  return p > 0.0 ? 2.0 * p / (a + b) : 0.0;
}

static double upwind_flux(double vel, double q_left, double q_right) {
  return vel > 0.0 ? vel * q_left : vel * q_right;
}

DPGEN_KERNEL void advect_vanleer_helper(DPGEN_IN const double* q, DPGEN_IN const double* u,
                                        DPGEN_OUT double* flux, int n) {
  for (int i = 1; i < n - 2; ++i) {
    double q_l = q[i] + 0.5 * vanleer(q[i] - q[i - 1], q[i + 1] - q[i]);
    double q_r = q[i + 1] - 0.5 * vanleer(q[i + 1] - q[i], q[i + 2] - q[i + 1]);
    flux[i] = upwind_flux(u[i], q_l, q_r);
  }
}
