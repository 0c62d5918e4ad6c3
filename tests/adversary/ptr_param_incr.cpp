#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ptr_param_incr(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  a++;
  for (int i = 0; i < n - 1; ++i)
    out[i] = a[i] * a[i];
}
