// adversary: [=] capture of a local that changes later (stale copy)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_copy_local_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double h) {
  double c = h;
  auto f = [=](int i) { return c * u[i] * u[i]; };
  c = 2.0 * h;
  for (int i = 0; i < n; ++i) out[i] = f(i) + c * u[i];
}
