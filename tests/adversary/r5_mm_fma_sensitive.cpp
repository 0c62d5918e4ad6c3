// adversary: element a*b + c (FMA-contractible): the scan and the tie test must agree bit for bit
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_fma_sensitive(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_IN const double* c, DPGEN_OUT double* out, int n) {
  double m = -4.0;
  for (int i = 0; i < n; ++i) m = fmax(m, a[i] * b[i] + c[i]);
  out[0] = m;
}
