#include "dpgen/annotate.hpp"
DPGEN_KERNEL void rowsum_noinit(DPGEN_IN const double* a, DPGEN_OUT double* r, int n) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      r[j] += a[j * n + i] * a[j * n + i];
}
