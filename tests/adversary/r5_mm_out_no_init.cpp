// adversary: *err = fmax(*err, ...) without setting *err first (documented rejection)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_out_no_init(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(r[i]));
}
