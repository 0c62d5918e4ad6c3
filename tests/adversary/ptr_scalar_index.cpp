#include "dpgen/annotate.hpp"
DPGEN_KERNEL void ptr_scalar_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n, const int* off) {
  for (int i = 0; i < n; ++i)
    out[i] = a[i + *off] * a[i];
}
