// adversary: per-row accumulator in a triangle, stored, and the stored value read in a later nest
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_per_row_read_later_nest(DPGEN_IN const double* a, DPGEN_OUT double* r,
                                                 DPGEN_OUT double* q, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i; ++j) s += a[j];
    r[i] = s * s;
  }
  for (int i = 0; i < n; ++i) q[i] = r[i] * a[i];
}
