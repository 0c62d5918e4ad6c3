// adversary: constant row through a kernel-level local const int top = m - 1
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_row_from_local(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m) {
  const int top = m - 1;
  for (int i = 0; i < n; ++i) {
    b[top][i] = a[top][i] * a[0][i];
    b[0][i] = a[top][i];
  }
}
