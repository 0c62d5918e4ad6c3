// adversary: m1 = max a; m2 = max a[i] / m1 (= 1): its derivative is zero
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_normalised_max_is_one(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double m1 = 0.5;
  for (int i = 0; i < n; ++i) m1 = fmax(m1, a[i]);
  double m2 = 0.0;
  for (int i = 0; i < n; ++i) m2 = fmax(m2, a[i] / m1);
  out[0] = m2 + m1;
}
