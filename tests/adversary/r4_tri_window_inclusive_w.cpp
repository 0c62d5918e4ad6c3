// adversary: window max(0,i-w)..min(n-1,i+w) inclusive, param w
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_window_inclusive_w(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int w) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::max(0, i - w); j <= std::min(n - 1, i + w); ++j) s += a[j] * a[j] * (j - i + 0.5);
    out[i] = s;
  }
}
