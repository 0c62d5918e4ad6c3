// The rewrite the diagnostic names: sum into a work array, the norm into another output.
#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void split_norm_other(DPGEN_IN const double* a, DPGEN_OUT double* sum, DPGEN_OUT double* nrm, int n) {
  sum[0] = 1.0;
  for (int i = 0; i < n; ++i)
    sum[0] += a[i] * a[i];
  nrm[0] = std::sqrt(sum[0]);
}
