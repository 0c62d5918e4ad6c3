// adversary: explicit capture list [u, h]
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_explicit_list(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double h) {
  auto d = [u, h](int i) { return (u[i + 1] - u[i]) * h * u[i]; };
  for (int i = 0; i + 1 < n; ++i) out[i] = d(i);
}
