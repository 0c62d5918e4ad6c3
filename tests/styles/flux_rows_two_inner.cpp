// Directional differences computed row by row: one outer loop over rows with
// two inner loops of different lengths (x faces, then cell averages), a shape
// common in split-direction hydro sweeps.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void flux_rows_two_inner(DPGEN_IN const double* q, DPGEN_OUT double* dx_q,
                                      DPGEN_OUT double* avg, int nx, int ny) {
  for (int j = 0; j < ny; ++j) {
    for (int i = 1; i < nx; ++i)
      dx_q[j * nx + i] = q[j * nx + i] - q[j * nx + i - 1];
    for (int i = 0; i < nx - 2; ++i)
      avg[j * nx + i] = 0.5 * (q[j * nx + i] + q[j * nx + i + 2]);
  }
}
