// r3: += from a mirrored loop, then += after the loop into o[0] (unsigned n >= 1)
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_accum_after_loop_rev(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) o[n - 1 - i] += a[i] * a[i];
  o[0] += a[n - 1] * 3.0 * a[0];
}
