#include "dpgen/annotate.hpp"
DPGEN_KERNEL void loop_then_other(DPGEN_IN const double* a, DPGEN_OUT double* o1, DPGEN_OUT double* o2, int n) {
  for (int i = 0; i < n; ++i)
    o1[i] = a[i] * a[i];
  o2[0] = o1[n - 1] * 2.0 + o1[0];
}
