// adversary: tridiagonal setup as codes write it: diag/upper of row j and a guess of row j + 1
#include "dpgen/annotate.hpp"
#include <cmath>
#include <algorithm>

DPGEN_KERNEL void r5_lw_tridiag_setup(DPGEN_IN const double* k, DPGEN_OUT double* d, DPGEN_OUT double* up, int n) {
  int j;
  for (j = 0; j < n; j++) {
    d[j] = k[j] + k[j + 1];
    up[j] = -k[j + 1];
    d[j + 1] = k[j + 1];
  }
}
