// Leapfrog 2D wave equation in single precision with a per-cell wave speed,
// __restrict__ pointers (GNU spelling).
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void wave2d_float_restrict(DPGEN_IN const float* __restrict__ u,
                                        DPGEN_IN const float* __restrict__ u_prev,
                                        DPGEN_IN const float* __restrict__ c2,
                                        DPGEN_OUT float* __restrict__ u_next, int nx, int ny,
                                        float dt2_h2) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i) {
      const int k = j * nx + i;
      u_next[k] = 2.0f * u[k] - u_prev[k] +
                  dt2_h2 * c2[k] * (u[k - 1] + u[k + 1] + u[k - nx] + u[k + nx] - 4.0f * u[k]);
    }
}
