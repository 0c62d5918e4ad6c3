// adversary: for (j = min(n-1,i+1); j >= max(0,i-1); --j)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_tri_minmax_reverse(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = std::min(n - 1, i + 1); j >= std::max(0, i - 1); --j) s = s * 0.5 + a[j] * a[j];
    out[i] = s;
  }
}
