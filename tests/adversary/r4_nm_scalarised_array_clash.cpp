// adversary: local array w[2] next to user locals w_0 and w_0_1
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_scalarised_array_clash(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  const double w_0 = 7.0, w_1 = 11.0;
  w[0] = 3.0;
  const double w_0_1 = 13.0;
  for (int i = 0; i < n; ++i) out[i] = (w[0] + w_0 * w_0_1) * u[i] * u[i] + w[1] * w_1 * u[i];
}
