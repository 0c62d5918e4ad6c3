#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_into_other(DPGEN_IN const double* a, DPGEN_OUT double* s, DPGEN_OUT double* o, int n) {
  s[0] = 0;
  for (int i = 0; i < n; ++i)
    s[0] += a[i] * a[i];
  o[0] = s[0] * s[0];
}
