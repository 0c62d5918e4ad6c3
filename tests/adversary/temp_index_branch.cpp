#include "dpgen/annotate.hpp"
DPGEN_KERNEL void temp_index_branch(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  double t = 1.0;
  for (int i = 0; i < n; ++i) {
    if (i > 0)
      t = a[i - 1];
    out[i] = t * a[i];
  }
}
