// adversary: constant loop m = 4 down to 0 step 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_par_unroll_down2(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const double w[5] = {1, 2, 3, 4, 5};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 4; m >= 0; m -= 2) s = s * 0.5 + w[m] * u[i + m];
    out[i] = s * s;
  }
}
