// adversary: fmax into a local, read in an expression
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_fmax_local(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m = -10.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * b[i]);
  out[0] = m * m + std::sin(m);
}
