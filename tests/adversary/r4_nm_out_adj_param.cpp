// adversary: output out and an input named out_adj
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_out_adj_param(DPGEN_IN const double* out_adj, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) out[i] = out_adj[i] * out_adj[i];
}
