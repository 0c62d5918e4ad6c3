// adversary: the max used in a later loop's condition and value
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_result_in_condition(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
  for (int i = 0; i < n; ++i)
    u[i] = fabs(a[i]) > 0.5 * m ? a[i] * m : 0.25 * a[i];
}
