// Neighbours clamped to the grid, the way codes write a zero-gradient (Neumann) boundary
// without a branch: `u[std::max(i - 1, 0)]`, `u[std::min(i + 1, n - 1)]`, std::clamp, and in
// 2D on the row index. dpgen reads each clamped index as the choice it is (i >= 1 ? i - 1 : 0)
// and gathers the adjoint cell by cell, as for a conditional index.
#include "dpgen/annotate.hpp"

#include <algorithm>

// A three-point smoother with reflecting ends.
DPGEN_KERNEL void clamped_smooth(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = 0.25 * u[std::max(i - 1, 0)] + 0.5 * u[i] + 0.25 * u[std::min(i + 1, n - 1)];
}

// A nonlinear five-point operator with clamped rows and columns, through locals.
DPGEN_KERNEL void clamped_diffusion2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int nx,
                                      int ny, double k) {
  for (int j = 0; j < ny; ++j) {
    const int jm = std::max(j - 1, 0), jp = std::min(j + 1, ny - 1);
    for (int i = 0; i < nx; ++i) {
      const int im = std::max(i - 1, 0), ip = std::min(i + 1, nx - 1);
      const double c = u[j * nx + i];
      out[j * nx + i] =
          c + k * c * (u[j * nx + im] + u[j * nx + ip] + u[jm * nx + i] + u[jp * nx + i] - 4.0 * c);
    }
  }
}

// A wider stencil: a one-sided std::min at distance 3 (gathered), and std::clamp to both ends
// at distance 2, whose adjoint stays in scatter form (which of 0 and n - 1 bounds the index
// depends on n, not on i: dpgen's remark says so).
DPGEN_KERNEL void clamped_wide(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int i = 0; i < n; ++i)
    v[i] = u[std::clamp(i - 2, 0, n - 1)] * u[std::clamp(i + 2, 0, n - 1)] -
           0.5 * u[std::min(i + 3, n - 1)];
}
