// adversary: IDX uses const int ld = nx + 2 * ng
#include "dpgen/annotate.hpp"
#define IDX(i, j) ((i) + ng + ((j) + ng) * ld)

DPGEN_KERNEL void r4_mac_ld_local(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  const int ng = 1;
  const int ld = n + 2 * ng;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      v[IDX(i, j)] = u[IDX(i - 1, j)] * u[IDX(i + 1, j)] + u[IDX(i, j - 1)] * u[IDX(i, j + 1)];
}
