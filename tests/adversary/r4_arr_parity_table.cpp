// adversary: std::array table read at a moving-parity counter
#include "dpgen/annotate.hpp"
#include <array>
#include <cmath>

DPGEN_KERNEL void r4_arr_parity_table(DPGEN_IN const double* a, DPGEN_OUT double* e, int n, int m) {
  const std::array<double, 2> w{0.5, 2.0};
  for (int j = 0; j < m; ++j)
    for (int i = j % 2; i < n; i += 2)
      e[j * n + i] = w[j % 2] * a[j * n + i] * a[j * n + i];
}
