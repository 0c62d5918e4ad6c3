// adversary: 2D, two work arrays fx, fy then update reading both
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a27_work2d_multi(DPGEN_IN const double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy,
                                   DPGEN_OUT double* qn, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx - 1; ++i) fx[j * nx + i] = q[j * nx + i + 1] * q[j * nx + i];
  for (int j = 0; j < ny - 1; ++j)
    for (int i = 0; i < nx; ++i) fy[j * nx + i] = q[(j + 1) * nx + i] - q[j * nx + i] * q[j * nx + i];
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      qn[j * nx + i] = q[j * nx + i] - (fx[j * nx + i] - fx[j * nx + i - 1]) * (fy[j * nx + i] - fy[(j - 1) * nx + i]);
}
