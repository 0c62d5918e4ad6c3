// r3: the (unsigned)k < (unsigned)n bounds idiom with an int k = i - 1 and int n
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_uns_bounds_trick(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int k = i - 1;
    double l = (unsigned)k < (unsigned)n ? a[k] : 0.0;
    o[i] = l * a[i] + a[i];
  }
}
