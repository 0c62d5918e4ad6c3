// adversary: lambda returning bool used in a condition
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_bool_predicate(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto up = [&](int i) -> bool { return u[i] > 0.0; };
  for (int i = 0; i < n; ++i) out[i] = up(i) ? u[i] * u[i] : -u[i];
}
