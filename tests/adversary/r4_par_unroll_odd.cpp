// adversary: constant loop m = 1, 3, 5 (m < 6, step 2)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_unroll_odd(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 1; m < 6; m += 2) s += m * u[i + m] * u[i + m - 1];
    out[i] = s;
  }
}
