// Semi-Lagrangian advection, 1D periodic: trace back x = i - dt*vel/dx and
// interpolate linearly. The read index is data-dependent, so its adjoint is
// scatter form; the weights carry the derivative w.r.t. vel.
#include "test_kernels.hpp"

#include <cmath>

DPGEN_KERNEL void semi_lagrangian(DPGEN_IN const double* q, DPGEN_IN const double* vel,
                                  DPGEN_OUT double* q_next, int n, double dt, double dx) {
  for (int i = 0; i < n; ++i) {
    double x = i - dt * vel[i] / dx;
    double fl = std::floor(x);
    double w = x - fl;
    int i0 = ((int)fl % n + n) % n;
    int i1 = (i0 + 1) % n;
    q_next[i] = (1.0 - w) * q[i0] + w * q[i1];
  }
}
