// adversary: lambda defined in the loop calls a lambda defined outside
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_in_loop_calls_outer(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto g = [&](int k) { return u[k] * u[k]; };
  for (int i = 1; i < n; ++i) {
    auto h = [&](int d) { return g(i - d) + g(i); };
    out[i] = h(1) * h(0);
  }
}
