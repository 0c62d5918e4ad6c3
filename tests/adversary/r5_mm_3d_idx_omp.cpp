// adversary: 3D max over an interior, IDX3 macro, omp
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX3(i, j, k) (((k) * ny + (j)) * nx + (i))

DPGEN_KERNEL void r5_mm_3d_idx_omp(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx, int ny, int nz) {
  double m = 0.0;
  #pragma omp parallel for collapse(2) reduction(max : m)
  for (int k = 1; k < nz - 1; ++k)
    for (int j = 1; j < ny - 1; ++j)
      for (int i = 1; i < nx - 1; ++i)
        m = std::max(m, std::fabs(u[IDX3(i + 1, j, k)] + u[IDX3(i, j, k - 1)] - 2.0 * u[IDX3(i, j, k)]));
  out[0] = m;
}
