// adversary: std::array subscript chosen by data
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_data_index(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> w{0.5, 2.0};
  for (int i = 0; i < n; ++i) out[i] = w[u[i] > 0.0 ? 1 : 0] * u[i] * u[i];
}
