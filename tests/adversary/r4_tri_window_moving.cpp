// adversary: window max(0,i-1)..min(n,i+2), both sides moving
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_window_moving(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - 1); j < std::min(n, i + 2); ++j) s += a[j] * a[i];
    out[i] = s;
  }
}
