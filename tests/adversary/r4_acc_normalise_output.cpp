// adversary: u[i] = a[i] / (1 + s*s) after the sum
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_normalise_output(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                          DPGEN_OUT double* u, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] / (1.0 + b[i] * b[i]);
  for (int i = 0; i < n; ++i) u[i] = a[i] / (1.0 + s * s);
}
