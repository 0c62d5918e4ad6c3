// adversary: lambda taking const double& and const auto
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_const_ref_param(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const auto f = [](const double& x, const double& y) { return x * y + x; };
  for (int i = 1; i < n; ++i) out[i] = f(u[i], u[i - 1]) * f(u[i - 1], 1.0);
}
