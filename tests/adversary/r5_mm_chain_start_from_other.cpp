// adversary: a second reduction starts from the first's result
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_chain_start_from_other(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {
  double m1 = a[0];
  for (int i = 1; i < n; ++i) m1 = fmax(m1, a[i]);
  double m2 = m1;
  for (int i = 0; i < n; ++i) m2 = fmax(m2, b[i]);
  out[0] = m1 * m2;
}
