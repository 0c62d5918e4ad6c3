#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_sumsq(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* loss, int n) {
  loss[0] = 0;
  for (int i = 0; i < n; ++i)
    loss[0] += a[i] * a[i] * b[i];
  for (int i = 1; i < n; ++i)
    loss[0] -= 0.5 * (a[i] - a[i - 1]) * (a[i] - a[i - 1]);
}
