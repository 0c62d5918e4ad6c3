// adversary: #define LAST (n - 1); if (i == LAST) and IDX-based pinned element
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>
#define LAST (n - 1)
#define IDX(i) ((i) + 1)

DPGEN_KERNEL void r5_pin_macro_idx(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  int i;
  for (i = 0; i < n; i++) {
    u[IDX(i)] = a[i] * a[i];
    if (i == LAST) u[0] = a[LAST] - a[0];
  }
}
