// adversary: a local named out_v / dpgen_sum_s_b while the output is out
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_local_out_v(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double out_v = 0.0, dpgen_sum_s_b = 1.0;
  for (int i = 0; i < n; ++i) { out_v += u[i]; dpgen_sum_s_b += u[i] * u[i]; }
  out[0] = out_v * dpgen_sum_s_b;
}
