// adversary: constant loop m <= 6 step 3 (0, 3, 6)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_unroll_le(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m <= 6; m += 3) s += (m + 1) * u[i + m] * u[i];
    out[i] = s;
  }
}
