#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_then_plus(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  s[0] = a[0];
  for (int i = 1; i < n; ++i)
    s[0] += a[i] * a[i - 1];
  s[0] += a[n - 1] * a[0];
}
