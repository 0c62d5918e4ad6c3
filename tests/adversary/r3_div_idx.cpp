// r3: int local with / in the index: o[i] = a[i / 2] * a[i] (non-affine read)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_div_idx(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int h = i / 2;
    o[i] = a[h] * a[i];
  }
}
