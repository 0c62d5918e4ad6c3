// r3: double -> int -> double cast of a value (zero derivative through the int)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_cast_floor(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int k = (int)(4.0 * a[i]);
    o[i] = (double)k * a[i] + a[i] * a[i];
  }
}
