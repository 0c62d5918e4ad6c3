// First-order upwind advection with a Fortran-callable interface: n, dt and
// dx by pointer; dt and dx dereferenced inside the loop body.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void advect_upwind_ptrscalars(const int* n, const double* dt, const double* dx,
                                           DPGEN_IN const double* q, DPGEN_IN const double* u,
                                           DPGEN_OUT double* q_new) {
  const int nn = *n;
  for (int i = 1; i < nn - 1; ++i) {
    double flux_r = u[i] > 0.0 ? u[i] * q[i] : u[i] * q[i + 1];
    double flux_l = u[i - 1] > 0.0 ? u[i - 1] * q[i - 1] : u[i - 1] * q[i];
    q_new[i] = q[i] - (*dt) / (*dx) * (flux_r - flux_l);
  }
}
