// adversary: constant loop m = 0..8 step 3 over a table
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_unroll_step3(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m < 9; m += 3) s += w[m] * u[i + m] * u[i + m];
    out[i] = s;
  }
}
