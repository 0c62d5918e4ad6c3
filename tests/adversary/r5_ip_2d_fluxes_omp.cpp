// adversary: 2D x/y fluxes from the old q (IDX macro, omp), then q updated in place
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_2d_fluxes_omp(DPGEN_INOUT double* q, DPGEN_OUT double* fx, DPGEN_OUT double* fy, int nx, int ny, double c) {
  int i, j;
#pragma omp parallel for private(i)
  for (j = 0; j < ny; j++)
    for (i = 1; i < nx; i++)
      fx[IDX(i, j)] = c * (q[IDX(i, j)] - q[IDX(i - 1, j)]);
#pragma omp parallel for private(i)
  for (j = 1; j < ny; j++)
    for (i = 0; i < nx; i++)
      fy[IDX(i, j)] = c * (q[IDX(i, j)] - q[IDX(i, j - 1)]) * q[IDX(i, j)];
#pragma omp parallel for private(i)
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      q[IDX(i, j)] += fx[IDX(i + 1, j)] - fx[IDX(i, j)] + fy[IDX(i, j + 1)] - fy[IDX(i, j)];
}
