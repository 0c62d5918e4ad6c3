// adversary: WRONG: [=] copies a local C array, the array changes before the call; the inlined call reads the new value
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_min_lam_array_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[1] = {1.0};
  auto f = [=](int i) { return w[0] * u[i]; };
  w[0] = 5.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}
