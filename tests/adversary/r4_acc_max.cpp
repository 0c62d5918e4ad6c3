// adversary: max reduction s = std::max(s, a[i]*a[i])
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r4_acc_max(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = -1.0;
  for (int i = 0; i < n; ++i) s = std::max(s, a[i] * (1.0 + 0.01 * i));
  out[0] = s * s;
}
