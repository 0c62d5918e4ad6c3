// adversary: lambda params named i_adj, u_adj, dpgen_t0
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_param_names_generated(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto f = [&](int i_adj, double u_adj) { const double dpgen_t0 = u[i_adj] * u_adj; return dpgen_t0 + u_adj; };
  for (int i = 0; i < n; ++i) out[i] = f(i, u[i] * u[i]);
}
