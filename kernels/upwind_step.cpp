// First-order upwind advection step on a periodic 1D grid (seed text, eq. 17):
//   d_next[i] = d[i] - dt * (up(i) * (d[i+1] - d[i]) + um(i) * (d[i] - d[i-1]))
// with up = min(u/dx, 0) looking downstream and um = max(u/dx, 0) upstream.
#include "kernels.hpp"

#include <algorithm>

DPGEN_KERNEL void upwind_step(DPGEN_IN const double* d, DPGEN_IN const double* u,
                              DPGEN_OUT double* d_next, int n, double dt,
                              double dx) {
  for (int i = 0; i < n; ++i) {
    const int ip = (i == n - 1) ? 0 : i + 1; // periodic right neighbour
    const int im = (i == 0) ? n - 1 : i - 1; // periodic left neighbour
    const double up = std::min(u[i] / dx, 0.0);
    const double um = std::max(u[i] / dx, 0.0);
    d_next[i] = d[i] - dt * (up * (d[ip] - d[i]) + um * (d[i] - d[im]));
  }
}
