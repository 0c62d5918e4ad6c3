// Boundary columns written next to an interior nest in the same row loop,
// as diffusion and hydro codes do (issue 20): f[j*nx + 0], the interior
// 1..nx-2, f[j*nx + nx - 1]. The rows are apart for nx >= 2, which dpgen
// cannot know: the adjoint checks it on entry.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void end_columns(DPGEN_IN const double* u, DPGEN_OUT double* f, int nx, int ny,
                              double r) {
  for (int j = 0; j < ny; ++j) {
    f[j * nx + 0] = u[j * nx + 0] * u[j * nx + 0];
    for (int i = 1; i < nx - 1; ++i)
      f[j * nx + i] = u[j * nx + i] + r * (u[j * nx + i - 1] - 2.0 * u[j * nx + i] +
                                           u[j * nx + i + 1]);
    f[j * nx + nx - 1] = 2.0 * u[j * nx + nx - 1];
  }
}
