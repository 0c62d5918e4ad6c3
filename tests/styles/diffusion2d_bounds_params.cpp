// 2D diffusion step on the index box [x_min, x_max] x [y_min, y_max]
// (inclusive), lower bounds and the leading dimension passed by the caller,
// which keeps halo cells outside the box.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void diffusion2d_bounds_params(DPGEN_IN const double* u, DPGEN_OUT double* un,
                                            int x_min, int x_max, int y_min, int y_max, int ld,
                                            double nu) {
  for (int j = y_min; j <= y_max; ++j)
    for (int i = x_min; i <= x_max; ++i)
      un[j * ld + i] = u[j * ld + i] + nu * (u[j * ld + i + 1] + u[j * ld + i - 1] +
                                             u[(j + 1) * ld + i] + u[(j - 1) * ld + i] -
                                             4.0 * u[j * ld + i]);
}
