// adversary: sum used in an index-dependent branch later
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_acc_index_branch(DPGEN_IN const double* a, DPGEN_OUT double* u, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i] * a[i];
  for (int i = 0; i < n; ++i) {
    if (i % 2 == 0) u[i] = a[i] * s;
    else if (i == n - 1) u[i] = s * s;
    else u[i] = a[i] - s;
  }
}
