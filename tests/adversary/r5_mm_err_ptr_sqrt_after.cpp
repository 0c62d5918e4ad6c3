// adversary: *err = max of squares, then *err = sqrt(*err) (read back after the loop)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_err_ptr_sqrt_after(DPGEN_IN const double* r, DPGEN_OUT double* err, int n) {
  *err = 1e-3;
  for (int i = 0; i < n; ++i) *err = fmax(*err, r[i] * r[i]);
  *err = std::sqrt(*err);
}
