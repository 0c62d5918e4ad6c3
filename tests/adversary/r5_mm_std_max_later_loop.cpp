// adversary: std::max of |a| read in a later loop
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_std_max_later_loop(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::fabs(a[i]));
  for (int i = 0; i < n; ++i) u[i] = a[i] / (1.0 + m);
}
