// adversary: v[i] = u[i-1]*u[i+1] on a moving-parity row
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_neighbours_step2(DPGEN_IN const double* u, DPGEN_OUT double* v, int n, int m) {
  for (int j = 0; j < m; ++j)
    for (int i = 1 + j % 2; i < n - 1; i += 2)
      v[j * n + i] = u[j * n + i - 1] * u[j * n + i + 1] + u[j * n + i];
}
