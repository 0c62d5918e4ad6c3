// 2D explicit heat step, C89 counters declared before the nest, an OpenMP
// pragma on the outer loop (inner counter made private by hand), i++/j++.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void heat2d_c89(DPGEN_IN const double* t, DPGEN_OUT double* t_new, int nx, int ny,
                             double rx, double ry)
{
  int i, j;
#pragma omp parallel for private(i)
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      t_new[j * nx + i] = t[j * nx + i] +
                          rx * (t[j * nx + i - 1] - 2.0 * t[j * nx + i] + t[j * nx + i + 1]) +
                          ry * (t[(j - 1) * nx + i] - 2.0 * t[j * nx + i] + t[(j + 1) * nx + i]);
}
