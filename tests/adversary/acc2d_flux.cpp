#include "dpgen/annotate.hpp"
DPGEN_KERNEL void acc2d_flux(DPGEN_IN const double* u, DPGEN_OUT double* r, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      r[j * nx + i] = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      double f = u[j * nx + i + 1] * u[j * nx + i];
      r[j * nx + i] -= f;
      r[j * nx + i + 1] += f;
    }
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double g = u[(j + 1) * nx + i] - u[j * nx + i] * u[j * nx + i];
      r[j * nx + i] -= g;
      r[(j + 1) * nx + i] += g;
    }
}
