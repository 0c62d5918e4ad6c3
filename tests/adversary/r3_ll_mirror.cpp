// r3: long long size, long counter, mirror read and mirror store
#include "dpgen/annotate.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
DPGEN_KERNEL void r3_ll_mirror(DPGEN_IN const double* a, DPGEN_OUT double* o, long long n) {
  for (long i = 0; i < n; ++i) o[n - 1 - i] = a[i] * a[i] - a[n - 1 - i];
}
