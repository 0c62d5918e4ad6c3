// Viscous Burgers step, upwinded convection; the difference quotients are
// temporaries declared once at function scope and overwritten per cell.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void burgers_private_temps(DPGEN_IN const double* u, DPGEN_OUT double* u_next, int n,
                                        double dt, double dx, double nu) {
  double a, dup, dum;
  for (int i = 1; i < n - 1; ++i) {
    a = u[i];
    dup = (u[i + 1] - u[i]) / dx;
    dum = (u[i] - u[i - 1]) / dx;
    u_next[i] = u[i] - dt * (a > 0.0 ? a * dum : a * dup) + nu * dt * (dup - dum) / dx;
  }
}
