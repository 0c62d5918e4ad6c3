// Viscous Burgers step, 1D periodic: centered advection plus diffusion.
#include "test_kernels.hpp"

DPGEN_KERNEL void burgers_step(DPGEN_IN const double* u, DPGEN_OUT double* u_next, int n,
                               double dt, double dx, double nu) {
  for (int i = 0; i < n; ++i) {
    int ip = i + 1 < n ? i + 1 : 0;
    int im = i > 0 ? i - 1 : n - 1;
    double adv = u[i] * (u[ip] - u[im]) / (2.0 * dx);
    double diff = nu * (u[ip] - 2.0 * u[i] + u[im]) / (dx * dx);
    u_next[i] = u[i] + dt * (diff - adv);
  }
}
