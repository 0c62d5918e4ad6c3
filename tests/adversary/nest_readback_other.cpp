#include "dpgen/annotate.hpp"
DPGEN_KERNEL void nest_readback_other(DPGEN_IN const double* a, DPGEN_OUT double* o1, DPGEN_OUT double* o2, int n) {
  for (int i = 0; i < n; ++i)
    o1[i] = a[i] * a[i];
  for (int i = 0; i < n - 1; ++i)
    o2[i] = o1[i + 1] * o1[i] - a[i];
}
