// adversary: std::array::at (rejected or right)
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_at(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> w{0.5, 1.5};
  for (int i = 0; i < n; ++i) out[i] = w.at(i % 2) * u[i] * u[i];
}
