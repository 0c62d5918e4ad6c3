// Set, sum in a loop, then add once more after it (a '+=' after the loop).
#include "dpgen/annotate.hpp"
DPGEN_KERNEL void split_reduce_plus(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  s[0] = a[0];
  for (int i = 0; i < n; ++i)
    s[0] += a[i] * a[i];
  s[0] += 3.0 * a[0];
}
