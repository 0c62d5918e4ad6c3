#include "dpgen/annotate.hpp"
DPGEN_KERNEL void countdown_int(DPGEN_IN const double* a, DPGEN_OUT double* out, int n) {
  for (int i = n - 1; i >= 1; --i)
    out[i] = a[i] - a[i - 1] * a[n - i];
}
