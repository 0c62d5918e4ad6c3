// r3: unsigned size, int counter compared with (int)n, mirror read n - i - 1
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_int_counter(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (int i = 0; i < (int)n; ++i) o[i] = a[n - i - 1] * a[i];
}
