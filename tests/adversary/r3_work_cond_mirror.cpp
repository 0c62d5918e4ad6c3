// r3: work array with a conditional overwrite that reads it back, then read mirrored by a later loop
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_work_cond_mirror(DPGEN_IN const double* a, DPGEN_OUT double* w, DPGEN_OUT double* o, unsigned n) {
  for (unsigned i = 0; i < n; ++i) {
    w[i] = a[i] * a[i];
    if (i > 0) w[i] = w[i] * a[i - 1];
  }
  for (unsigned i = 0; i < n; ++i) o[i] = w[n - 1 - i] + a[i];
}
