#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_then_assign(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  s[0] = a[0];
  for (int i = 1; i < n; ++i)
    s[0] += a[i] * a[i];
  s[0] = a[0] * 5.0;
}
