// adversary: explicit heat step in place: lap from the old u (IDX, C89), then u += dt * lap
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define IDX(i, j) ((j) * nx + (i))

DPGEN_KERNEL void r5_ip_heat_lap_work(DPGEN_INOUT double* u, DPGEN_OUT double* lap, int nx, int ny, double dt) {
  int i, j;
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      lap[IDX(i, j)] = u[IDX(i - 1, j)] + u[IDX(i + 1, j)] + u[IDX(i, j - 1)] + u[IDX(i, j + 1)] - 4.0 * u[IDX(i, j)];
  for (j = 1; j < ny - 1; j++)
    for (i = 1; i < nx - 1; i++)
      u[IDX(i, j)] = u[IDX(i, j)] + dt * lap[IDX(i, j)] * (1.0 + u[IDX(i, j)] * u[IDX(i, j)]);
}
