// adversary: red sweep writes v, black sweep reads v (the output) at red points
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_red_then_black(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  for (int j = 1; j < m - 1; ++j)
    for (int i = 1 + (j + 1) % 2; i < n - 1; i += 2)
      v[j * n + i] = 0.25 * (u[j * n + i - 1] + u[j * n + i + 1]) * u[j * n + i];
  for (int j = 1; j < m - 1; ++j)
    for (int i = 1 + j % 2; i < n - 1; i += 2)
      v[j * n + i] = 0.25 * (v[j * n + i - 1] * v[j * n + i + 1] + u[j * n + i]);
}
