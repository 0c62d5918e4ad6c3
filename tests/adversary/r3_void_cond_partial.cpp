// r3: void helper that assigns its double& only on one branch (the caller's prior value survives otherwise)
#include "dpgen/annotate.hpp"
static void lim(double l, double r, double& f) {
  if (l * r > 0) f = l * r;
}
DPGEN_KERNEL void r3_void_cond_partial(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 1; i < n; ++i) {
    double f = a[n - 1 - i] * 3.0;
    lim(a[i - 1], a[i], f);
    o[i] = f;
  }
}
