// r3: a user typedef of unsigned long for sizes (typedef unsigned long idx_t) with a mirror read
#include "dpgen/annotate.hpp"
typedef unsigned long idx_t;
DPGEN_KERNEL void r3_typedef_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, idx_t n) {
  for (idx_t i = 0; i < n; ++i) o[i] = a[n - 1 - i] * 2.0 + a[i] * a[i];
}
