// adversary: start from a[0], the loop includes index 0 (start and a[0] tie)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_start_a0_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = a[0];
  for (int i = 0; i < n; ++i)
    m = std::max(m, a[i]);
  out[0] = m * m;
}
