// r3: loop condition i != n, int
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_ne_cond(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i != n; ++i) o[i] = a[i] * a[n - 1 - i];
}
