// adversary: if (i == n - 1) in a stride-2 loop: iteration n - 1 exists only for odd n
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_pin_strided_last_maybe_missing(DPGEN_IN const double* a, DPGEN_OUT double* u, DPGEN_OUT double* last, int n) {
  for (int i = 0; i < n; i += 2) {
    u[i] = a[i] * 3.0;
    if (i == n - 1) last[0] = a[i] * a[i];
  }
}
