// adversary: bound j <= i / 2
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_tri_half_bound(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j <= i / 2; ++j) s += a[j] * a[i - j];
    r[i] = s;
  }
}
