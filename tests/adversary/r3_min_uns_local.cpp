// r3 minimal: an unsigned local m = i - 1 (int i) wraps at i = 0, so m < n is false there; dpgen: ptrdiff_t m = -1
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_min_uns_local(DPGEN_IN const double* a, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    unsigned m = i - 1;
    o[i] = m < (unsigned)n ? a[m] : a[i];
  }
}
