// adversary: std::array filled by an unrolled step-2 loop, read after
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_unroll_strided_store(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 4> b{};
    for (int m = 0; m < 4; m += 2) b[m] = u[i + m] * u[i + m];
    out[i] = b[0] + b[1] + b[2] * b[0] + b[3];
  }
}
