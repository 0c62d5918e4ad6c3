// adversary: a local reduced by two loops in turn
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_local_two_loops_chain(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -1.0;
  for (int i = 0; i < n; ++i) m = std::max(m, a[i]);
  for (int i = 0; i < n; ++i) m = std::max(m, b[i] * b[i]);
  out[0] = m * m;
}
