// adversary: std::array table captured by a lambda
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_in_lambda(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  constexpr std::array<double, 3> c = {-0.5, 0.0, 0.5};
  auto d = [&](int i) { return c[0] * u[i - 1] + c[1] * u[i] + c[2] * u[i + 1]; };
  for (int i = 1; i + 1 < n; ++i) out[i] = d(i) * d(i);
}
