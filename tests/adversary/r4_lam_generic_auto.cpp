// adversary: generic lambda [](auto x)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_generic_auto(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto cube = [](auto x) { return x * x * x; };
  for (int i = 0; i < n; ++i) out[i] = cube(u[i]) + cube(2.0) * u[i];
}
