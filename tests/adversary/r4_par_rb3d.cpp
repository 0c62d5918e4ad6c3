// adversary: 3D red-black start 1 + (j + k) % 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_rb3d(DPGEN_IN const double* u, DPGEN_OUT double* v, int n) {
  for (int k = 1; k < n - 1; ++k)
    for (int j = 1; j < n - 1; ++j)
      for (int i = 1 + (j + k) % 2; i < n - 1; i += 2) {
        const int c = (k * n + j) * n + i;
        v[c] = (u[c - 1] + u[c + 1] + u[c - n] + u[c + n] + u[c - n * n] + u[c + n * n]) * u[c];
      }
}
