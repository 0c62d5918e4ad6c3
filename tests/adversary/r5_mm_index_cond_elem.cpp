// adversary: the element uses the counter: fmax(m, i == 0 ? 0 : a[i] - a[i - 1])
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_index_cond_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, i == 0 ? 0.0 : a[i] - a[i - 1]);
  out[0] = m * m;
}
