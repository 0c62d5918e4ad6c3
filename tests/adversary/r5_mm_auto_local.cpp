// adversary: auto m = a[0]; if-update min with a C89 counter
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_auto_local(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  auto m = a[0] * 2.0;
  int i;
  for (i = 1; i < n; i++)
    if (2.0 * a[i] < m) m = 2.0 * a[i];
  out[0] = m;
}
