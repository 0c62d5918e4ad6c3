// r3: strided reads a[3 * i + 2] * a[3 * i] (input 3n), long counter
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_stride3(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (long i = 0; i < n; ++i) o[i] = a[3 * i + 2] * a[3 * i] - a[3 * i + 1];
}
