#include "dpgen/annotate.hpp"
DPGEN_KERNEL void temp_one_branch(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t = 0;
  for (int i = 0; i < n; ++i) {
    if (a[i] > 0)
      t = a[i] * a[i];
    out[i] = t;
  }
}
