#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reduce_normalize(DPGEN_IN const double* a, DPGEN_OUT double* s, DPGEN_OUT double* out, int n) {
  s[0] = 1.0;
  for (int i = 0; i < n; ++i)
    s[0] += a[i] * a[i];
  for (int i = 0; i < n; ++i)
    out[i] = a[i] / s[0];
}
