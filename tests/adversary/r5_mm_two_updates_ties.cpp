// adversary: two updates per iteration, ties across arrays
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_two_updates_ties(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) {
    m = std::max(m, a[i]);
    m = std::max(b[i], m);
  }
  out[0] = 3.0 * m;
}
