// adversary: a max and a min of the same data in one loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_range_same_loop(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double mx = a[0], mn = a[0];
  for (int i = 0; i < n; ++i) {
    mx = fmax(mx, a[i]);
    mn = fmin(mn, a[i]);
  }
  out[0] = mx - mn;
  out[1] = mx * mn;
}
