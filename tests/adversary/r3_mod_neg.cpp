// r3: int % of a negative numerator is negative: r = (i - 2) % 3 in -2..2, read a[r + 2]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_mod_neg(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int r = (i - 2) % 3;
    o[i] = a[r + 2] * a[i] + a[r + 2];
  }
}
