// adversary: loop bound t.size()
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_size_bound(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  const std::array<double, 3> w{1.0, 2.0, 3.0};
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (std::size_t m = 0; m < w.size(); ++m) s += w[m] * u[i + m];
    out[i] = s * s;
  }
}
