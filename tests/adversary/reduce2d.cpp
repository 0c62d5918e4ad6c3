#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce2d(DPGEN_IN const double* a, DPGEN_OUT double* loss, int n) {
  loss[0] = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      loss[0] += a[j * n + i] * a[i * n + j];
}
