// adversary: double** in place: row fluxes from the old grid, then the update
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_ip_rowptr_inout(DPGEN_INOUT double** u, DPGEN_OUT double* f, int nx, int ny) {
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx; ++i) f[j * nx + i] = u[j][i] - u[j][i - 1];
  for (int j = 0; j < ny; ++j)
    for (int i = 1; i < nx - 1; ++i) u[j][i] += 0.25 * (f[j * nx + i + 1] - f[j * nx + i]);
}
