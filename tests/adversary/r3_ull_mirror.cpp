// r3: unsigned long long size, unsigned counter, mirror read
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void r3_ull_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, unsigned long long n) {
  for (unsigned i = 0; i < n; ++i) o[i] = a[n - 1 - i] - a[i] * a[n - 1 - i];
}
