// r3: int half = n / 2 bound, reads a[2 * i] and a[half + i]
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_half_local(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  int half = n / 2;
  for (int i = 0; i < half; ++i) o[i] = a[2 * i] * a[half + i];
}
