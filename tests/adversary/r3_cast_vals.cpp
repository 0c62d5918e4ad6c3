// r3: int <-> double casts in values: (double)i, (double)(n - i), static_cast of an int product
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_cast_vals(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    double w = (double)(n - i) / (double)n;
    o[i] = w * a[i] * a[i] + static_cast<double>(i * i) * a[n - 1 - i];
  }
}
