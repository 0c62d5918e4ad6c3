// adversary: *err reduced over two loops in turn (the second starts from the first)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_err_two_loops_chain(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* err, int n) {
  *err = 0.0;
  for (int i = 0; i < n; ++i) *err = fmax(*err, fabs(a[i]));
  for (int i = 0; i < n; ++i) *err = fmax(*err, 2.0 * fabs(b[i]));
}
