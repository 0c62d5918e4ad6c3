// adversary: max over a[idx[i]] (a data-dependent read)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_gather_index(DPGEN_IN const double* a, const int* idx, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[idx[i]] * (1.0 + 0.1 * i));
  out[0] = m;
}
