// Semi-Lagrangian self-advection, periodic: sample u at the cell centre,
// trace back x - dt*u, interpolate linearly. The sample index depends on u
// itself, so dpgen gives this read a scatter-form adjoint.
#include "example_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void advect_self_semi_lagrangian(DPGEN_IN const double* u, DPGEN_OUT double* u_out,
                                              int n, double dt, double dx) {
  for (int i = 0; i < n; ++i) {
    const double x = i - dt * u[i] / dx; // departure point, in cells
    const double fl = std::floor(x);
    const double w = x - fl;
    int i0 = static_cast<int>(fl) % n;
    if (i0 < 0)
      i0 += n;
    const int i1 = i0 == n - 1 ? 0 : i0 + 1;
    u_out[i] = (1.0 - w) * u[i0] + w * u[i1];
  }
}
