// adversary: lambda [=] capturing a local C array by copy
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_capture_carray_copy(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  double w[3] = {0.25, 0.5, 0.25};
  auto smooth = [=](int i) { return w[0] * u[i] + w[1] * u[i + 1] * u[i + 1] + w[2] * u[i + 2]; };
  for (int i = 0; i + 2 < n; ++i) out[i] = smooth(i);
}
