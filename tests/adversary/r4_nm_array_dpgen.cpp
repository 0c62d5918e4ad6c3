// adversary: std::array named dpgen_sum_s_v and a local c_i
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_nm_array_dpgen(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 2> dpgen_sum_s_v{0.5, 1.5};
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += dpgen_sum_s_v[i % 2] * u[i];
  for (int c_i = 0; c_i < n; ++c_i) out[c_i] = s * u[c_i];
}
