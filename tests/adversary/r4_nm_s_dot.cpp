// adversary: accumulator s next to a local s_dot and s_adj
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_s_dot(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  const double s_dot = 2.0 * s;
  const double s_adj = s_dot * s;
  out[0] = s_adj + s_dot;
}
