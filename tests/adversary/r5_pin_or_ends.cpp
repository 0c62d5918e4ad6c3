// adversary: if (i == 0 || i == n - 1) e[0] = ...: two iterations store e[0]
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_or_ends(DPGEN_IN const double* a, DPGEN_OUT double* e, int n) {
  for (int i = 0; i < n; ++i)
    if (i == 0 || i == n - 1) e[0] = a[i] * a[i];
}
