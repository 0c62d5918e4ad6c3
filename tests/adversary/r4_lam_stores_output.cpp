// adversary: lambda that stores into the output
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_stores_output(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto put = [&](int i, double v) { out[i] = v * u[i]; };
  for (int i = 0; i < n; ++i) put(i, u[i] + 1.0);
}
