// r3: store index through a ternary that is the identity except at the ends: o[i < 1 ? 0 : i] with int locals
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_store_clamped_ends(DPGEN_IN const double* a, DPGEN_OUT double* o, long n) {
  for (long i = 0; i < n; ++i) {
    long k = n - 1 - i;
    long m = k < 0 ? 0 : k;
    o[m] = a[i] * a[k];
  }
}
