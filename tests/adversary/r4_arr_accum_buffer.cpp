// adversary: std::array buffer accumulated with += then read
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_accum_buffer(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 2> b{};
    for (int m = 0; m < 4; ++m) b[m % 2] += u[i + m] * u[i + m];
    out[i] = b[0] * b[1];
  }
}
