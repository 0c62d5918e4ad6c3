// adversary: std::array of std::array
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_2d(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<std::array<double, 2>, 2> M{{{1.0, 2.0}, {3.0, 4.0}}};
  for (int i = 0; i < n; ++i) out[i] = M[0][1] * u[i] * u[i] + M[1][0] * u[i + 1];
}
