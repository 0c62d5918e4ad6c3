#include "dpgen/annotate.hpp"
DPGEN_KERNEL void reverse_read(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[n - 1 - i] = a[i] * a[n - 1 - i] + a[i];
}
