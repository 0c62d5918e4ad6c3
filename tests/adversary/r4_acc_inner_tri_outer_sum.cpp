// adversary: triangular inner accumulator feeding an outer accumulator
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_inner_tri_outer_sum(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double tot = 0;
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = i; j < n; ++j) s += a[j];
    tot += s * s;
  }
  out[0] = tot;
}
