// adversary: red half into v, black half into w, both reading u
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_two_halves_two_outs(DPGEN_IN const double* u, DPGEN_OUT double* v,
                                             DPGEN_OUT double* w, int n, int m) {
  for (int j = 0; j < m; ++j) {
    for (int i = j % 2; i < n; i += 2) v[j * n + i] = u[j * n + i] * u[j * n + i];
    for (int i = 1 + j % 2; i < n; i += 2) w[j * n + i] = u[j * n + i] * v[j * n + i - 1];
  }
}
