// adversary: err[0] a max, err[1] a min of the same loop (output elements)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_two_out_elems(DPGEN_IN const double* a, DPGEN_OUT double* err, int n) {
  err[0] = -1.0;
  err[1] = 1.0;
  for (int i = 0; i < n; ++i) {
    err[0] = fmax(err[0], a[i]);
    err[1] = fmin(err[1], a[i]);
  }
}
