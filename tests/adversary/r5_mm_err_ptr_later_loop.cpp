// adversary: *err = 0; *err = fmax(*err, |r|); the output read by a later loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_err_ptr_later_loop(DPGEN_IN const double* r, DPGEN_OUT double* err, DPGEN_OUT double* u, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(r[i]));
  for (int i = 0; i < n; ++i) u[i] = r[i] / (1.0 + *err);
}
