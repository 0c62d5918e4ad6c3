// adversary: an accumulator named dpgen_sum_s and one named s
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_nm_dpgen_sum_s(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double s = 0.0, dpgen_sum_s = 1.0;
  for (int i = 0; i < n; ++i) {
    s += a[i] * a[i];
    dpgen_sum_s += a[i];
  }
  out[0] = s * dpgen_sum_s;
}
