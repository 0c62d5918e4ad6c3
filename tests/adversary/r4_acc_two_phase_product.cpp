// adversary: t = s, s reset, s re-accumulated; out = t*s
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_two_phase_product(DPGEN_IN const double* a, DPGEN_IN const double* b,
                                           DPGEN_OUT double* out, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i];
  double t = s;
  s = 0;
  for (int i = 0; i < n; ++i) s += b[i] * b[i];
  out[0] = t * s + t;
}
