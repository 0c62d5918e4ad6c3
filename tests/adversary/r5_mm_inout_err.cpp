// adversary: err DPGEN_INOUT: err[0] = fmax(err[0], |r|) starts from the caller's value, an input here
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_inout_err(DPGEN_INOUT double* err, DPGEN_IN const double* r, int n) {
  for (int i = 0; i < n; ++i) err[0] = fmax(err[0], fabs(r[i]));
}
