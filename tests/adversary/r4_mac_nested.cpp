// adversary: macro using another macro with a local
#include "dpgen/annotate.hpp"
#define LD (nx + 2)
#define IDX(i, j) ((i) + 1 + ((j) + 1) * LD)

DPGEN_KERNEL void r4_mac_nested(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  const int nx = n;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      v[IDX(i, j)] = u[IDX(i - 1, j)] - u[IDX(i, j)] * u[IDX(i, j - 1)];
}
