// adversary: if (x > mx) mx = x; else if (x < mn) mn = x;: the min runs under a condition on mx (read inside its loop)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_minmax_elseif(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double mx = a[0], mn = a[0];
  for (int i = 1; i < n; ++i) {
    if (a[i] > mx) mx = a[i];
    else if (a[i] < mn) mn = a[i];
  }
  out[0] = mx - mn;
  out[1] = mx * mn;
}
