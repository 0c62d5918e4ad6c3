// adversary: [&] capture of a local that changes each iteration
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_ref_local_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double c = 0.0;
  auto f = [&](int i) { return c * u[i]; };
  for (int i = 0; i < n; ++i) {
    c = u[i] * u[i];
    out[i] = f(i) + c;
  }
}
