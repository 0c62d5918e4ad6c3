// adversary: if (i + j == n - 1) s[0] = ...: n iterations store s[0]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_antidiag_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i + j == n - 1) s[0] = a[j * n + i] * a[j * n + i];
}
