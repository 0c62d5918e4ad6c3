// adversary: [=] copy of a scalar changed inside the loop before each call
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_scalar_copy_in_loop_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 1.0;
  auto f = [=](int i) { return c * u[i]; };
  for (int i = 0; i < n; ++i) {
    c = u[i];
    out[i] = f(i) + c;
  }
}
