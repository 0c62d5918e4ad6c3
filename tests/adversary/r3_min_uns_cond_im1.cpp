// r3 minimal: unsigned i - 1 < n is false at i = 0 (wrap); dpgen drops the condition (signed: always true)
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cstddef>
DPGEN_KERNEL void r3_min_uns_cond_im1(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[i] = i - 1 < n ? a[i - 1] : a[i];
}
