// Divergence of a MAC-grid velocity (u on x faces: ny x (nx+1), v on y faces:
// (ny+1) x nx) accumulated into a cell-centred right-hand side, weighted by a
// cell porosity; i++/j++.
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void divergence_accumulate2d(DPGEN_IN const double* u, DPGEN_IN const double* v,
                                          DPGEN_IN const double* phi, DPGEN_OUT double* div,
                                          int nx, int ny, double inv_h) {
  for (int j = 0; j < ny; j++)
    for (int i = 0; i < nx; i++)
      div[j * nx + i] += phi[j * nx + i] * inv_h *
                         (u[j * (nx + 1) + i + 1] - u[j * (nx + 1) + i] + v[(j + 1) * nx + i] -
                          v[j * nx + i]);
}
