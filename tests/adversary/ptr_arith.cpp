#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ptr_arith(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  const double* ap = a + 1;
  for (int i = 0; i < n - 1; ++i)
    out[i] = ap[i] * a[i];
}
