#include "dpgen/annotate.hpp"
DPGEN_KERNEL void int_branch_temp(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i) {
    int k = i;
    if (i > 0)
      k = i - 1;
    else
      k = n - 1;
    out[i] = a[k] * a[i];
  }
}
