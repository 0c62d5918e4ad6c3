// adversary: [&] captures a local array that changes before the call (must see the new value)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_array_ref_changes(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  auto f = [&](int i) { return w[0] * u[i] + w[1]; };
  w[0] = 4.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}
