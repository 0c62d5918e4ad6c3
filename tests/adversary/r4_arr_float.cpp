// adversary: std::array<float, 3> table in a float kernel
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_float(DPGEN_IN const float* u, DPGEN_OUT float* out, int n) {
  const std::array<float, 3> w{0.25f, 0.5f, 0.25f};
  for (int i = 1; i + 1 < n; ++i) out[i] = w[0] * u[i - 1] + w[1] * u[i] * u[i] + w[2] * u[i + 1];
}
