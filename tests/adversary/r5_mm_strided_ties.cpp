// adversary: min over a stride-2 loop; the skipped odd element is smaller
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_strided_ties(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 10.0;
  for (int i = 0; i < n; i += 2) m = fmin(m, a[i]);
  out[0] = m * m + m;
}
