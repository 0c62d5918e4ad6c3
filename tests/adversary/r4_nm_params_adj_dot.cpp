// adversary: inputs named u, u_adj, u_dot
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_params_adj_dot(DPGEN_IN const double* u, DPGEN_IN const double* u_adj,
                                       DPGEN_IN const double* u_dot, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = u[i] * u_adj[i] + u_dot[i] * u_dot[i];
}
