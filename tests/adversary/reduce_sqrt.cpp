#include "dpgen/annotate.hpp"
#include <cmath>
DPGEN_KERNEL void reduce_sqrt(DPGEN_IN const double* a, DPGEN_OUT double* nrm, int n) {
  nrm[0] = 1.0;
  for (int i = 0; i < n; ++i)
    nrm[0] += a[i] * a[i];
  nrm[0] = std::sqrt(nrm[0]);
}
