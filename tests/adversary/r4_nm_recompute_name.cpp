// adversary: a helper named like the generated recompute/nest functions
#include "dpgen/annotate.hpp"

static inline double r4_nm_recompute_name_recompute(double x) { return x * x; }
static inline double r4_nm_recompute_name_nest1_adjoint(double x) { return 2.0 * x; }
DPGEN_KERNEL void r4_nm_recompute_name(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += r4_nm_recompute_name_recompute(u[i]);
  for (int i = 0; i < n; ++i) out[i] = s * r4_nm_recompute_name_nest1_adjoint(u[i]);
}
