// adversary: *err reduced, then overwritten with another value after the loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_err_ptr_overwritten(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  err[0] = 0.0;
  for (int i = 0; i < n; ++i) err[0] = fmax(err[0], r[i]);
  err[1] = 2.0 * err[0];
  err[0] = r[0] * 0.0 + 1.0;
}
