// adversary: constant rows stored in param-branch arms
#include "dpgen/annotate.hpp"

DPGEN_KERNEL void r4_rp_rows_in_branch(DPGEN_IN double** a, DPGEN_OUT double** b, int n, int m, int flag) {
  if (flag == 0) {
    for (int i = 0; i < n; ++i) { b[0][i] = a[1][i]; b[1][i] = a[0][i] * a[0][i]; }
  } else {
    for (int i = 0; i < n; ++i) { b[0][i] = a[m - 1][i] * a[0][i]; b[1][i] = 0.0; }
  }
}
