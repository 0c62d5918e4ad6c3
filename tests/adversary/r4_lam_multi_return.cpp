// adversary: lambda with three return arms
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_lam_multi_return(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto lim = [](double a, double b) -> double {
    if (a > b) return a * b;
    if (a < -b) return -a;
    return std::sin(a) + b;
  };
  for (int i = 1; i < n; ++i) out[i] = lim(u[i], u[i - 1]);
}
