// adversary: if (i == 2 * j) s[0] = ...: several iterations store s[0]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_i_eq_2j_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == 2 * j) s[0] = std::sin(a[j * n + i]);
}
