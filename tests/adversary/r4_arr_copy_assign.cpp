// adversary: std::array copied by assignment
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_copy_assign(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    std::array<double, 2> a{u[i], u[i] * u[i]};
    std::array<double, 2> b = a;
    b[0] = 3.0;
    out[i] = a[0] * b[1] + b[0] * a[1];
  }
}
