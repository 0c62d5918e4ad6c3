// adversary: REJECTED, should be accepted: inclusive upper bound j <= std::min(n - 1, i + 1) (the exclusive j < std::min(n, i + 2) is accepted)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_min_le_min_bound(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j <= std::min(n - 1, i + 1); ++j) s += a[j] * a[j];
    out[i] = s;
  }
}
