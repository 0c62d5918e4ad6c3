// adversary: max in one arm, min of another local in the other (flag parameter)
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_mm_branch_param_arms(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, int flag) {
  if (flag == 0) {
    double m = -1.0;
    for (int i = 0; i < n; ++i) m = fmax(m, a[i]);
    out[0] = m;
  } else {
    double m = 1.0;
    for (int i = 0; i < n; ++i) m = fmin(m, a[i]);
    out[0] = m * m;
  }
}
