// adversary: the element is a data branch: fmax(m, a[i] > 0 ? a[i] : -2 * a[i])
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_branchy_elem(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] > 0.0 ? a[i] : -2.0 * a[i]);
  out[0] = m * m;
}
