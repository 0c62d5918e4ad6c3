// adversary: std::array buffer filled forward, read reversed
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_buffer_then_reverse(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 3> d;
    for (int m = 0; m < 3; ++m) d[m] = u[i + m] * (m + 1);
    out[i] = d[2] * d[0] - d[1] * d[1];
  }
}
