// adversary: WRONG: a mutable lambda's by-copy capture persists across calls (c = 2, 4, 8, ...); the inlined call restarts from the kernel's c every iteration
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_min_lam_mutable_state(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [c, u](int i) mutable { c = c * 2.0; return c * u[i]; };
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}
