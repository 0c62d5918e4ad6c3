// adversary: small local arrays, unrolled constant loops, line buffer
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void a25_local_arrays(DPGEN_IN const double* u, DPGEN_OUT double* o, int n) {
  const double w[3] = {0.25, 0.5, 0.25};
  for (int i = 2; i < n - 2; ++i) {
    double v[5];
    for (int m = 0; m < 5; ++m) v[m] = u[i - 2 + m] * u[i - 2 + m];
    double s = 0;
    for (int m = 0; m < 3; ++m) s += w[m] * v[m + 1];
    v[2] = s * v[0];
    o[i] = v[2] + v[4] - v[2] * v[3];
  }
}
