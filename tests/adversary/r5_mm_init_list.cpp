// adversary: m = std::max({m, a[i], b[i]})
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_init_list(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = std::max({m, a[i], b[i]});
  out[0] = m * m;
}
