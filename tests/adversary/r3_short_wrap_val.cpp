// r3: short arithmetic: (short)(i * 20000) wraps; used in the value only
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_short_wrap_val(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    short s = (short)(i * 20000);
    o[i] = a[i] * (double)s * 1e-4;
  }
}
