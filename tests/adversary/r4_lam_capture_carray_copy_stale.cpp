// adversary: lambda [=] copies a C array that changes afterwards
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_capture_carray_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[2] = {1.0, 2.0};
  auto f = [=](int i) { return w[0] * u[i] + w[1] * u[i] * u[i]; };
  w[0] = 5.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) + w[0] * u[i];
}
