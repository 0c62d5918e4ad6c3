// adversary: [=] copies a std::array that changes before the call
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_lam_stdarray_copy_stale(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  std::array<double, 2> w{1.0, 2.0};
  auto f = [=](int i) { return w[0] * u[i] + w[1]; };
  w[0] = 4.0;
  for (int i = 0; i < n; ++i) out[i] = f(i) * u[i];
}
