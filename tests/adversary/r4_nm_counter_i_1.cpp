// adversary: a local i_1 while the lambda call renames its counter i to i_1
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_counter_i_1(DPGEN_IN const double* u, DPGEN_OUT double* out, int n) {
  auto f = [&](int i) { return u[i] * u[i]; };
  for (int i = 0; i < n; ++i) {
    const int i_1 = n - 1 - i;
    out[i] = f(i) + u[i_1];
  }
}
