// r3: int k = i - 2 compared with an unsigned size: k < n is false when k < 0 (k converts to unsigned)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_int_vs_uns_cmp(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (int i = 0; i < (int)n; ++i) {
    int k = i - 2;
    o[i] = (k < n) ? a[k] * a[i] : a[i] * a[i];
  }
}
