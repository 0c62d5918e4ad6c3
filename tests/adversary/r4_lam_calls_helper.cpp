// adversary: lambda calling a static helper
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

static inline double r4_sq(double x) { return x * x; }
DPGEN_KERNEL void r4_lam_calls_helper(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto energy = [&](int i) { return r4_sq(u[i]) + r4_sq(u[i + 1] - u[i]); };
  for (int i = 0; i + 1 < n; ++i) out[i] = energy(i) * u[i];
}
