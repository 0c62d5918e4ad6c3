// r3: int division of a negative numerator truncates toward zero: q = (i - 3) / 2, read a[q + 2]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_div_neg(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int q = (i - 3) / 2;
    o[i] = a[q + 2] * a[i];
  }
}
