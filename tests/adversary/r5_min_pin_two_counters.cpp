// adversary: MINIMAL: if (i == j) tr[0] = a[i]: n iterations store tr[0], the adjoint credits all of them
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_min_pin_two_counters(DPGEN_IN const double* a, DPGEN_OUT double* tr, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) tr[0] = a[i];
}
