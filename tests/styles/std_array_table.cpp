// std::array locals the way modern C++ codes write them (issue 20): a
// constexpr coefficient table of a 4th-order derivative, and a small buffer
// filled in one loop and read in the next, both in loops dpgen unrolls.
#include "dpgen/annotate.hpp"

#include <array>
#include <cmath>

DPGEN_KERNEL void fd4_std_array(DPGEN_IN const double* u, DPGEN_OUT double* du, int n,
                                double inv_h) {
  constexpr std::array<double, 5> c = {1.0 / 12, -2.0 / 3, 0.0, 2.0 / 3, -1.0 / 12};
  for (int i = 2; i < n - 2; ++i) {
    double s = 0;
    for (int m = 0; m < 5; ++m)
      s += c[m] * u[i - 2 + m];
    du[i] = s * inv_h;
  }
}

DPGEN_KERNEL void limiter_std_array(DPGEN_IN const double* q, DPGEN_OUT double* out, int n) {
  for (int i = 1; i < n - 1; ++i) {
    std::array<double, 3> d{};
    for (int m = 0; m < 3; ++m)
      d[m] = q[i - 1 + m] * q[i - 1 + m];
    const std::array<double, 3> w{0.25, 0.5, 0.25};
    double s = 0;
    for (int m = 0; m < 3; ++m)
      s += w[m] * std::tanh(d[m]);
    out[i] = s;
  }
}
