// r3 minimal: int k < unsigned n converts k to unsigned (k = -1 is not < n); dpgen compares signed
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_int_vs_uns(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (int i = 0; i < (int)n; ++i) {
    int k = i - 1;
    o[i] = k < n ? a[k] : a[i];
  }
}
