// adversary: if (i == j) tr[0] = ...: n iterations store tr[0] (the last wins)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_diag_same_elem(DPGEN_IN const double* a, DPGEN_OUT double* tr, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j) tr[0] = a[j * n + i] * a[j * n + i];
}
