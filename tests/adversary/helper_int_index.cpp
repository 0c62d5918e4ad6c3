#include "dpgen/annotate.hpp"
static int wrap(int i, int n) {
  if (i < 0)
    return i + n;
  if (i >= n)
    return i - n;
  return i;
}
DPGEN_KERNEL void helper_int_index(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = 0; i < n; ++i)
    out[i] = a[wrap(i + 1, n)] * a[wrap(i - 1, n)];
}
