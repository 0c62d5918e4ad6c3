// adversary: lambda calling a lambda
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_lam_calls_lambda(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto grad = [&](int i) { return u[i + 1] - u[i]; };
  auto flux = [&](int i) { return grad(i) * 0.5 * (u[i] + u[i + 1]); };
  for (int i = 1; i + 1 < n; ++i) out[i] = flux(i) - flux(i - 1);
}
