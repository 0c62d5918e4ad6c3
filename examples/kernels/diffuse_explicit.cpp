// Explicit diffusion, periodic: u + dt*nu*laplace(u), 3-point Laplacian.
#include "example_kernels.hpp"

DPGEN_KERNEL void diffuse_explicit(DPGEN_IN const double* u, DPGEN_OUT double* u_out, int n,
                                   double dt, double nu, double dx) {
  for (int i = 0; i < n; ++i) {
    const int ip = i == n - 1 ? 0 : i + 1;
    const int im = i == 0 ? n - 1 : i - 1;
    u_out[i] = u[i] + dt * nu * (u[ip] - 2.0 * u[i] + u[im]) / (dx * dx);
  }
}
