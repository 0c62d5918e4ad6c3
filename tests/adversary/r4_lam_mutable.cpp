// adversary: mutable lambda with a counter (should be rejected or right)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_mutable(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [c, u](int i) mutable { c = c * 2.0; return c * u[i]; };
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}
