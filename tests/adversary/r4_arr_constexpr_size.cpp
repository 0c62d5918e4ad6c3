// adversary: std::array<double, K> with constexpr int K
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_constexpr_size(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  constexpr int K = 4;
  const std::array<double, K> w{1.0, -1.0, 2.0, -2.0};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int m = 0; m < K; ++m) s += w[m] * u[i + m] * u[i];
    out[i] = s;
  }
}
