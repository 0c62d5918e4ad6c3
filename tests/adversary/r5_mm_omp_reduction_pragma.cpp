// adversary: #pragma omp parallel for reduction(max:err) over a 2D interior (C89, IDX macro)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_mm_omp_reduction_pragma(DPGEN_IN const double* u, DPGEN_IN const double* f, DPGEN_OUT double* res, int nx, int ny) {
  int i, j;
  double err = 0.0;
#pragma omp parallel for private(i) reduction(max : err)
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++) {
      double r = f[IDX(i, j)] - (4.0 * u[IDX(i, j)] - u[IDX(i - 1, j)] - u[IDX(i + 1, j)] - u[IDX(i, j - 1)] - u[IDX(i, j + 1)]);
      err = fmax(err, fabs(r));
    }
  res[0] = std::sqrt(err + 1.0);
}
