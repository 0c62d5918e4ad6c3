// adversary: s = s + a[i]*a[i] in a C89 style with declaration at top
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_s_eq_s_plus(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int i;
  double s, t;
  s = 0.0;
  t = 1.0;
  for (i = 0; i < n; i++) {
    s = s + a[i] * a[i];
    t = t - a[i];
  }
  for (i = 0; i < n; i++) u[i] = s * a[i] + t;
}
