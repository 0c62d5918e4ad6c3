// adversary: lambda with a loop inside (stencil sum)
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_loop_inside(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto box = [&](int i) {
    double s = 0;
    for (int m = 0; m < 3; ++m) s += u[i + m] * u[i + m];
    return s;
  };
  for (int i = 0; i + 2 < n; ++i) out[i] = box(i);
}
